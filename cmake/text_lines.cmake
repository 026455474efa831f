# The lines of a text file as a CMake list, for the scripts that read tables and dictionaries.
# Brackets and semicolons would change how a list splits: they are hidden in the list (@LB@,
# @RB@, @SC@) and brought back one line at a time.

# text_lines(FILE OUT): the lines of FILE, hidden, into OUT.
function(text_lines file out)
  file(READ ${file} text)
  string(REPLACE "[" "@LB@" text "${text}")
  string(REPLACE "]" "@RB@" text "${text}")
  string(REPLACE ";" "@SC@" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

# shown_line(VAR): the line in VAR as the file has it.
function(shown_line var)
  set(line "${${var}}")
  string(REPLACE "@LB@" "[" line "${line}")
  string(REPLACE "@RB@" "]" line "${line}")
  string(REPLACE "@SC@" ";" line "${line}")
  set(${var} "${line}" PARENT_SCOPE)
endfunction()
