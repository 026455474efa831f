# Runs the crosscheck tool (CROSSCHECK) on every line of TABLE and checks its exit status and
# that its output (stdout and stderr) names the culprit. A line is
#   STATUS | CULPRIT | ARGUMENTS [| STDIN]
# ARGUMENTS are split as a shell would; @DATA@ is tests/data, @HERE@ this folder, @CORPORA@ the
# corpora folder and @WORK@ a fresh scratch folder (WORK), which holds symbolic links `loop` (to
# itself), `dangling` (to nowhere/x) and `under_a_file` (to a name under a file), a FIFO `fifo.json`, a sparse `oversized.json` of 65 MiB,
# `device_case/mesh_device.json` whose mesh is /dev/zero and `looping_folder/` with a case and a
# link `up` to its parent; @LONG_PATH@ is a relative path of 5,000 characters and @LONG_NAME@ a
# name of 300. A run that ends by a signal (a crash)
# or with another status fails the test, as does one past 60 s; every failing line is listed
# before the test fails.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/empty)
file(MAKE_DIRECTORY ${WORK}/shrunk_into)  # a folder to shrink into
file(WRITE ${WORK}/blocked/obb_obb "")  # a folder for case files whose query folder is a file
file(CREATE_LINK loop ${WORK}/loop SYMBOLIC)
file(CREATE_LINK nowhere/x ${WORK}/dangling SYMBOLIC)
file(CREATE_LINK blocked/obb_obb/x ${WORK}/under_a_file SYMBOLIC)
# Files no test data can hold: a FIFO, a sparse file past the 64 MiB limit, a mesh that is a device.
execute_process(COMMAND mkfifo ${WORK}/fifo.json)
file(TOUCH ${WORK}/oversized.json)
execute_process(COMMAND truncate -s 65M ${WORK}/oversized.json)
file(COPY ${DATA}/hostile/mesh_device.json DESTINATION ${WORK}/device_case)
file(COPY ${DATA}/hostile/meshes/triangle.obj DESTINATION ${WORK}/device_case/meshes)
file(CREATE_LINK /dev/zero ${WORK}/device_case/meshes/device.obj SYMBOLIC)
file(MAKE_DIRECTORY ${WORK}/looping_folder)
file(COPY ${CORPORA}/sphere_sphere/00a705170f21ad00.json DESTINATION ${WORK}/looping_folder)
file(CREATE_LINK .. ${WORK}/looping_folder/up SYMBOLIC)
string(REPEAT "a/" 2500 long_path)
string(REPEAT "n" 300 long_name)
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/text_lines.cmake)
text_lines(${TABLE} lines)
set(ran 0)
set(failed 0)
foreach(line IN LISTS lines)
  if(line MATCHES "^[ ]*(#|$)")
    continue()
  endif()
  shown_line(line)
  string(REPLACE "@DATA@" "${DATA}" line "${line}")
  string(REPLACE "@HERE@" "${CMAKE_CURRENT_LIST_DIR}" line "${line}")
  string(REPLACE "@CORPORA@" "${CORPORA}" line "${line}")
  string(REPLACE "@WORK@" "${WORK}" line "${line}")
  string(REPLACE "@LONG_PATH@" "${long_path}" line "${line}")
  string(REPLACE "@LONG_NAME@" "${long_name}" line "${line}")
  if(NOT line MATCHES "^([0-9]+) \\| ([^|]*) \\|[ ]?([^|]*)( \\| (.*))?$")
    message(SEND_ERROR "${TABLE}: a line not of the form STATUS | CULPRIT | ARGUMENTS [| STDIN]: ${line}")
    continue()
  endif()
  set(expected_status ${CMAKE_MATCH_1})
  set(culprit "${CMAKE_MATCH_2}")
  separate_arguments(arguments UNIX_COMMAND "${CMAKE_MATCH_3}")
  set(input /dev/null)
  if(NOT "${CMAKE_MATCH_5}" STREQUAL "")
    set(input "${CMAKE_MATCH_5}")
  endif()
  execute_process(COMMAND ${CROSSCHECK} ${arguments} WORKING_DIRECTORY ${WORK} INPUT_FILE ${input}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  math(EXPR ran "${ran} + 1")
  string(FIND "${out}${err}" "${culprit}" at)
  if(NOT status STREQUAL expected_status OR at EQUAL -1)
    math(EXPR failed "${failed} + 1")
    string(SUBSTRING "${out}" 0 400 out)
    message("FAILED: crosscheck ${CMAKE_MATCH_3}\n  expected status ${expected_status} and \"${culprit}\"; "
            "got status ${status}\n  stderr: ${err}  stdout (start): ${out}")
  endif()
endforeach()
message("${ran} invocations, ${failed} failed")
if(failed GREATER 0)
  message(FATAL_ERROR "${failed} of ${ran} invocations did not end as the table says")
endif()
