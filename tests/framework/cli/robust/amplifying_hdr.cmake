# Writes OUT: a valid run-length Radiance .hdr of 32767 x 5000 pixels in 10 MB (issue 31: such a
# file decodes to 190 times its size; a 50 MB one to 9.4 GB). Every scanline is the shortest the
# format allows: the marker 2 2 127 255 (width 32767), then for each of the 4 channels 258 runs of
# 127 equal bytes and one of 1 (a run is a count byte 128 + n and the value). No byte is 0, which
# a CMake string cannot hold.
#   cmake -DOUT=path/amplifying.hdr -P amplifying_hdr.cmake
cmake_minimum_required(VERSION 3.18)
if(NOT DEFINED OUT)
  message(FATAL_ERROR "amplifying_hdr.cmake: give -DOUT=FILE")
endif()
set(_w 32767)
set(_h 5000)
string(ASCII 2 2 127 255 _marker)
set(_line "${_marker}")
foreach(_value 64 64 64 128)   # r g b, and the exponent 128: each channel 0.25
  string(ASCII 255 ${_value} _run127)
  string(ASCII 129 ${_value} _run1)
  string(REPEAT "${_run127}" 258 _runs)
  string(APPEND _line "${_runs}${_run1}")
endforeach()
string(REPEAT "${_line}" ${_h} _pixels)
file(WRITE "${OUT}" "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ${_h} +X ${_w}\n${_pixels}")
