#!/bin/sh
# limited.sh KB COMMAND [ARG...]: runs COMMAND with at most KB kilobytes of address space (ulimit -v),
# so that a test sees an allocation the command should never make fail, instead of the machine
# providing it (tests/framework/cli/CMakeLists.txt).
ulimit -v "$1" || exit 125
shift
exec "$@"
