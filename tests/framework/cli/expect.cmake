# Runs one command and checks what it did. Used by the command-line tests (CMakeLists.txt here):
#
#   cmake [-DEXIT=N] [-DSTDOUT_REGEX=RE] [-DSTDERR_REGEX=RE] [-DSTDERR_LINES=N]
#         [-DFILE=PATH -DFILE_REGEX=RE] [-DNOT_WRITTEN=PATH|PATH...] [-DUNCHANGED=PATH|PATH...]
#         -P expect.cmake -- COMMAND [ARG...]
#
#   EXIT          the exit code the command must return (default 0). A crash (a signal) always fails.
#   STDOUT_REGEX  a regular expression (CMake syntax) stdout must match somewhere
#   STDERR_REGEX  the same for stderr
#   STDERR_LINES  the exact number of lines on stderr (e.g. 1: "one clear line")
#   FILE          a file the command must write: removed before the command runs, then its whole
#                 content must match FILE_REGEX (use ^ and $ to match it exactly)
#   NOT_WRITTEN   paths (files or folders, separated by '|') the command must not leave behind:
#                 removed before the command runs, checked to be absent after it
#   UNCHANGED     files (separated by '|') that must exist before the command runs and hold the
#                 same bytes after it (inputs an output must not overwrite)
#
# Everything after "--" is the command, passed as is (no shell).
cmake_minimum_required(VERSION 3.18)

set(_cmd "")
set(_found FALSE)
math(EXPR _last "${CMAKE_ARGC} - 1")
foreach(_i RANGE ${_last})
  if(_found)
    string(REPLACE ";" "\\;" _arg "${CMAKE_ARGV${_i}}")   # keep a ';' inside an argument
    list(APPEND _cmd "${_arg}")
  elseif(CMAKE_ARGV${_i} STREQUAL "--")
    set(_found TRUE)
  endif()
endforeach()
if(NOT _cmd)
  message(FATAL_ERROR "expect.cmake: no command given (put it after --)")
endif()
if(NOT DEFINED EXIT)
  set(EXIT 0)
endif()

if(DEFINED FILE)
  file(REMOVE "${FILE}")
endif()
set(_absent "")
if(DEFINED NOT_WRITTEN)
  string(REPLACE "|" ";" _absent "${NOT_WRITTEN}")
  foreach(_p ${_absent})
    file(REMOVE_RECURSE "${_p}")
  endforeach()
endif()

set(_kept "")
set(_hashes "")
if(DEFINED UNCHANGED)
  string(REPLACE "|" ";" _kept "${UNCHANGED}")
  foreach(_p ${_kept})
    if(NOT EXISTS "${_p}")
      message(FATAL_ERROR "expect.cmake: ${_p} (UNCHANGED) does not exist before the command")
    endif()
    file(SHA256 "${_p}" _hash)
    list(APPEND _hashes "${_hash}")
  endforeach()
endif()

execute_process(COMMAND ${_cmd}
                RESULT_VARIABLE _rc
                OUTPUT_VARIABLE _out
                ERROR_VARIABLE _err)

string(REPLACE ";" " " _shown "${_cmd}")
set(_report "command: ${_shown}\nexit: ${_rc}\n--- stdout ---\n${_out}--- stderr ---\n${_err}--------------")
set(_failures "")

if(NOT _rc MATCHES "^[0-9]+$")
  string(APPEND _failures "  the command did not exit normally (${_rc}): a crash or a signal\n")
elseif(NOT _rc EQUAL EXIT)
  string(APPEND _failures "  exit code ${_rc}, expected ${EXIT}\n")
endif()
if(DEFINED STDOUT_REGEX AND NOT _out MATCHES "${STDOUT_REGEX}")
  string(APPEND _failures "  stdout does not match: ${STDOUT_REGEX}\n")
endif()
if(DEFINED STDERR_REGEX AND NOT _err MATCHES "${STDERR_REGEX}")
  string(APPEND _failures "  stderr does not match: ${STDERR_REGEX}\n")
endif()
if(DEFINED STDERR_LINES)
  string(REGEX REPLACE "\n$" "" _trimmed "${_err}")
  if(_trimmed STREQUAL "")
    set(_n 0)
  else()
    string(REGEX MATCHALL "\n" _newlines "${_trimmed}")
    list(LENGTH _newlines _n)
    math(EXPR _n "${_n} + 1")
  endif()
  if(NOT _n EQUAL STDERR_LINES)
    string(APPEND _failures "  stderr has ${_n} line(s), expected ${STDERR_LINES}\n")
  endif()
endif()
if(DEFINED FILE)
  if(NOT EXISTS "${FILE}")
    string(APPEND _failures "  the command did not write ${FILE}\n")
  else()
    file(READ "${FILE}" _content)
    if(DEFINED FILE_REGEX AND NOT _content MATCHES "${FILE_REGEX}")
      string(APPEND _failures "  ${FILE} does not match: ${FILE_REGEX}\n--- ${FILE} ---\n${_content}\n")
    endif()
  endif()
endif()

foreach(_p ${_absent})
  if(EXISTS "${_p}")
    string(APPEND _failures "  the command left ${_p} behind\n")
  endif()
endforeach()

set(_i 0)
foreach(_p ${_kept})
  list(GET _hashes ${_i} _before)
  math(EXPR _i "${_i} + 1")
  if(NOT EXISTS "${_p}")
    string(APPEND _failures "  the command removed ${_p}\n")
  else()
    file(SHA256 "${_p}" _after)
    if(NOT _after STREQUAL _before)
      string(APPEND _failures "  the command changed ${_p} (an input it must not overwrite)\n")
    endif()
  endif()
endforeach()

if(_failures)
  message(FATAL_ERROR "${_report}\nFAILED:\n${_failures}")
endif()
message(STATUS "${_report}\nok")
