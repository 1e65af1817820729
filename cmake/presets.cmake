# Writes CMakePresets.json from the lesson folders (lessons/NN-name): the release preset, `mine`
# (every lesson from assignments/), one `mine-NN` per lesson (lesson NN from assignments/, every
# other lesson from its reference where the tree has one), `asan`, and a build preset for each. A new lesson folder gets
# its preset by running this again:
#   cmake --build build --target presets        (or: cmake -DSOURCE=. -DOUT=CMakePresets.json -P cmake/presets.cmake)
# The test course_presets_in_sync (-DCHECK=1) fails while CMakePresets.json is stale.
if(NOT SOURCE OR NOT OUT)
  message(FATAL_ERROR "usage: cmake -DSOURCE=<repository> -DOUT=<file> -P cmake/presets.cmake")
endif()

file(GLOB _lessons LIST_DIRECTORIES true RELATIVE ${SOURCE}/lessons ${SOURCE}/lessons/[0-9][0-9]-*)
list(SORT _lessons)

# "Lesson 3 (Path tracing)": the number without its leading zero and the README's title.
function(lesson_title NAME OUT)
  string(SUBSTRING ${NAME} 0 2 _nn)
  math(EXPR _n "${_nn}")
  set(_title "")
  if(EXISTS ${SOURCE}/lessons/${NAME}/README.md)
    file(STRINGS ${SOURCE}/lessons/${NAME}/README.md _first LIMIT_COUNT 1 ENCODING UTF-8)
    string(REGEX REPLACE "^# Lesson [0-9]+ [^A-Za-z]* *" "" _title "${_first}")
  endif()
  if(_title STREQUAL "")
    set(_title ${NAME})
  endif()
  string(REPLACE "\"" "'" _title "${_title}")
  set(${OUT} "Lesson ${_n} (${_title})" PARENT_SCOPE)
endfunction()

set(_configure "")
set(_build "")
macro(add_preset NAME DISPLAY BINARY VARIABLES)
  string(APPEND _configure "    {\n      \"name\": \"${NAME}\",\n      \"displayName\": \"${DISPLAY}\",\n"
                           "      \"binaryDir\": \"\${sourceDir}/${BINARY}\",\n      \"cacheVariables\": {\n${VARIABLES}      }\n    },\n")
  string(APPEND _build "    {\n      \"name\": \"${NAME}\",\n      \"configurePreset\": \"${NAME}\"\n    },\n")
endmacro()

set(_release "        \"CMAKE_BUILD_TYPE\": \"Release\"\n")
add_preset(release "Release (the default: what scripts/setup.sh and scripts/test.sh build)" build "${_release}")
add_preset(mine "Every lesson from assignments/ (your files, even the lessons whose reference is released)" build
           "        \"CMAKE_BUILD_TYPE\": \"Release\",\n        \"PATHSPACE_STUDENT\": \"all\"\n")
foreach(_lesson ${_lessons})
  string(SUBSTRING ${_lesson} 0 2 _nn)
  lesson_title(${_lesson} _title)
  add_preset(mine-${_nn} "${_title} from assignments/, every other lesson from its reference where this tree has one (the handout: the released lessons)" build
             "        \"CMAKE_BUILD_TYPE\": \"Release\",\n        \"PATHSPACE_STUDENT\": \"${_nn}\"\n")
endforeach()
add_preset(asan "AddressSanitizer + UndefinedBehaviorSanitizer (every test, several times slower)" build-asan
           "        \"CMAKE_BUILD_TYPE\": \"RelWithDebInfo\",\n        \"CMAKE_CXX_FLAGS\": \"-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer\",\n        \"CMAKE_EXE_LINKER_FLAGS\": \"-fsanitize=address,undefined\",\n        \"PATHSPACE_TEST_TIMEOUT\": \"1500\"\n")

# No comma after the last entry of a list.
string(REGEX REPLACE ",\n$" "\n" _configure "${_configure}")
string(REGEX REPLACE ",\n$" "\n" _build "${_build}")
string(CONCAT _json "{\n  \"version\": 3,\n  \"cmakeMinimumRequired\": {\n    \"major\": 3,\n    \"minor\": 21,\n    \"patch\": 0\n  },\n"
                  "  \"configurePresets\": [\n${_configure}  ],\n  \"buildPresets\": [\n${_build}  ],\n"
                  "  \"testPresets\": [\n    {\n      \"name\": \"asan\",\n      \"configurePreset\": \"asan\",\n"
                  "      \"output\": {\n        \"outputOnFailure\": true\n      },\n      \"execution\": {\n"
                  "        \"timeout\": 1500\n      },\n      \"environment\": {\n"
                  "        \"UBSAN_OPTIONS\": \"print_stacktrace=1\",\n        \"ASAN_OPTIONS\": \"detect_leaks=1\"\n"
                  "      }\n    }\n  ]\n}\n")
# Valid JSON, or cmake --preset fails for every student (string(JSON) parses it).
string(JSON _count LENGTH "${_json}" configurePresets)
if(CHECK)
  file(READ ${OUT} _have)
  if(NOT _have STREQUAL _json)
    message(FATAL_ERROR "${OUT} is not what the lesson folders make: run cmake --build build --target presets")
  endif()
  message(STATUS "${OUT}: one preset per lesson folder")
else()
  file(WRITE ${OUT} "${_json}")
endif()
