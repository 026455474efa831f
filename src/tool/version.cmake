# Writes version.h for the crosscheck tool: the project's version (VERSION) and the commit of
# the source tree (SOURCE), with "-dirty" when it has uncommitted changes ("unknown" outside
# git). Run at every build; the file is rewritten only when its text changes.
execute_process(COMMAND git -C ${SOURCE} rev-parse --short=12 HEAD OUTPUT_VARIABLE commit
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git -C ${SOURCE} diff --quiet HEAD -- RESULT_VARIABLE dirty ERROR_QUIET)
  if(dirty)
    string(APPEND commit "-dirty")
  endif()
endif()
string(CONCAT text "// Written by src/tool/version.cmake at build time.\n#pragma once\n"
         "#define CROSSCHECK_VERSION \"${VERSION}\"\n#define CROSSCHECK_COMMIT \"${commit}\"\n")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
