# Same bytes out: renders every registered integrator on a few small scenes, and the pyramid,
# and compares the SHA-256 of every output image with the stored list (sha256.txt, next to this
# file). It guards refactorings of the framework's loops (framework/tasks.h): a change there must
# not change a single bit of any algorithm's image. Each combination is rendered with 1 and 2
# threads; both must give the stored bytes.
#
#   cmake -DPATHSPACE=build/pathspace -DOUT=build/bytes -P tests/framework/bytes/bytes.cmake            (check)
#   cmake -DPATHSPACE=build/pathspace -DOUT=build/bytes -DWRITE=ON -P tests/framework/bytes/bytes.cmake (write)
#
# The write mode regenerates sha256.txt from the current build. Do that (and say why in the
# commit) only when an algorithm's result is MEANT to change, e.g. new MIS weights in lesson 7
# change every bpt image; never to make a refactoring pass.
cmake_minimum_required(VERSION 3.16)
if(NOT PATHSPACE OR NOT OUT)
  message(FATAL_ERROR "usage: cmake -DPATHSPACE=path/to/pathspace -DOUT=dir [-DWRITE=ON] -P bytes.cmake")
endif()
# Relative paths are taken from where cmake runs (a relative OUT once made the pyramid's images
# invisible to the file search, and write mode dropped their hashes).
get_filename_component(OUT "${OUT}" ABSOLUTE)
get_filename_component(PATHSPACE "${PATHSPACE}" ABSOLUTE)
get_filename_component(_here ${CMAKE_CURRENT_LIST_FILE} DIRECTORY)
get_filename_component(_root ${_here}/../../.. ABSOLUTE)
set(_list ${_here}/sha256.txt)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

# Small copies of the scenes (24 x 16 pixels): Cornell box (area light), a point light, glass
# (delta BSDFs, light inside a sphere), a background light, glossy Phong.
set(_scenes cornell-box cornell-point-light glass-lamp cornell-background cornell-glossy)
foreach(_s ${_scenes})
  file(READ ${_root}/scenes/${_s}.scene _text)
  string(REGEX REPLACE "resolution [0-9]+ [0-9]+" "resolution 24 16" _text "${_text}")
  file(WRITE ${OUT}/${_s}.scene "${_text}")
endforeach()

# Every integrator the program knows: an unknown name makes it list them all
# ("unknown algorithm '?' (known: a, b, ...)", framework/integrator.cpp).
execute_process(COMMAND ${PATHSPACE} render ${OUT}/cornell-box.scene --algo ? --out ${OUT}/none.pfm
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _o ERROR_VARIABLE _e)
if(NOT "${_e}" MATCHES "\\(known: ([^)]*)\\)")
  message(FATAL_ERROR "could not read the list of algorithms from pathspace's error message:\n${_o}${_e}")
endif()
string(REPLACE ", " ";" _algos "${CMAKE_MATCH_1}")
list(LENGTH _algos _n)
if(_n LESS 3)
  message(FATAL_ERROR "only ${_n} algorithms known: ${_algos}")
endif()

set(_got "")   # lines "name sha256"
set(_failed "")
function(_run NAME)
  # ARGN: the command's arguments; the output files are ${OUT}/${NAME}*.pfm
  execute_process(COMMAND ${PATHSPACE} ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _o ERROR_VARIABLE _e)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${NAME}: pathspace ${ARGN} failed (${_rc}):\n${_o}${_e}")
  endif()
endfunction()

foreach(_s ${_scenes})
  foreach(_a ${_algos})
    foreach(_t 1 2)
      # An integrator may refuse a scene it cannot render at all (Integrator::checkScene, e.g.
      # lesson 11's radiosity: diffuse quads only): exit 1 and one error naming the scene file,
      # whose stored "hash" is then the word "refused" (so a refusal cannot come or go unseen).
      set(_args render ${OUT}/${_s}.scene --algo ${_a} --spp 3 --seed 7 --threads ${_t} --no-progress
                --out ${OUT}/${_a}-${_s}-t${_t}.pfm)
      execute_process(COMMAND ${PATHSPACE} ${_args} RESULT_VARIABLE _rc OUTPUT_VARIABLE _o ERROR_VARIABLE _e)
      if(_rc EQUAL 1 AND _e MATCHES "^pathspace: error: [^\n]*${_s}\\.scene")
        set(_h${_t} refused)
      elseif(NOT _rc EQUAL 0)
        message(FATAL_ERROR "${_a}-${_s}-t${_t}: pathspace ${_args} failed (${_rc}):\n${_o}${_e}")
      else()
        file(SHA256 ${OUT}/${_a}-${_s}-t${_t}.pfm _h${_t})
      endif()
    endforeach()
    if(NOT _h1 STREQUAL _h2)
      list(APPEND _failed "algorithm ${_a} on ${_s}: 1 and 2 threads give different images")
    endif()
    list(APPEND _got "render/${_a}/${_s} ${_h1}")
  endforeach()
endforeach()

# The pyramid: every per-technique image, unweighted and weighted, 1 and 2 threads.
foreach(_s cornell-box cornell-point-light)
  foreach(_t 1 2)
    _run(pyramid-${_s}-t${_t} pyramid ${OUT}/${_s}.scene --max-length 3 --spp 3 --seed 7 --threads ${_t}
         --out ${OUT}/pyramid-${_s}-t${_t})
  endforeach()
  file(GLOB _pfms RELATIVE ${OUT} ${OUT}/pyramid-${_s}-t1-*.pfm)
  list(SORT _pfms)
  foreach(_f ${_pfms})
    string(REPLACE "-t1-" "-t2-" _f2 ${_f})
    file(SHA256 ${OUT}/${_f} _h1)
    file(SHA256 ${OUT}/${_f2} _h2)
    string(REGEX REPLACE "^pyramid-${_s}-t1-(.*)\\.pfm$" "\\1" _tech ${_f})
    if(NOT _h1 STREQUAL _h2)
      list(APPEND _failed "pyramid technique ${_tech} on ${_s}: 1 and 2 threads give different images")
    endif()
    list(APPEND _got "pyramid/${_tech}/${_s} ${_h1}")
  endforeach()
endforeach()

string(REPLACE ";" "\n" _gotText "${_got}")
if(WRITE)
  file(WRITE ${_list} "${_gotText}\n")
  list(LENGTH _got _n)
  message(STATUS "wrote ${_n} hashes to ${_list}")
  if(_failed)
    string(REPLACE ";" "\n  " _f "${_failed}")
    message(FATAL_ERROR "not thread-count independent:\n  ${_f}")
  endif()
  return()
endif()

file(STRINGS ${_list} _stored)
foreach(_line ${_stored})
  string(REGEX REPLACE " .*" "" _name "${_line}")
  string(REGEX REPLACE ".* " "" _hash "${_line}")
  set(_want_${_name} ${_hash})
  list(APPEND _storedNames ${_name})
endforeach()
foreach(_line ${_got})
  string(REGEX REPLACE " .*" "" _name "${_line}")
  string(REGEX REPLACE ".* " "" _hash "${_line}")
  string(REPLACE "/" ";" _parts ${_name})
  list(GET _parts 0 _kind)
  list(GET _parts 1 _what)
  list(GET _parts 2 _scene)
  if(NOT DEFINED _want_${_name})
    list(APPEND _failed "${_kind} ${_what} on ${_scene}: no stored hash (a new algorithm? regenerate with -DWRITE=ON)")
  elseif(NOT _want_${_name} STREQUAL _hash)
    list(APPEND _failed "${_kind} ${_what} on ${_scene}: the image's bytes changed (expected SHA-256 ${_want_${_name}}, got ${_hash})")
  endif()
  list(REMOVE_ITEM _storedNames ${_name})
endforeach()
foreach(_name ${_storedNames})
  list(APPEND _failed "${_name}: stored but no longer rendered (an algorithm was removed or renamed?)")
endforeach()
if(_failed)
  string(REPLACE ";" "\n  " _f "${_failed}")
  message(FATAL_ERROR "same bytes out: ${_f}\n(outputs in ${OUT}; if the change is meant, regenerate the list: "
                      "cmake -DPATHSPACE=... -DOUT=... -DWRITE=ON -P tests/framework/bytes/bytes.cmake)")
endif()
list(LENGTH _got _n)
message(STATUS "same bytes out: ${_n} images as stored")
