#!/usr/bin/env bash
# Portable C++17, proved (README, "Platforms"): builds the whole repository with compilers and
# standard libraries other than CI's GCC 12 + libstdc++, with every warning an error, and runs the
# whole test suite in each build: the graded tests (and graded-test-count: none may be missing),
# the framework's tests (framework-same-bytes: the stored image hashes hold there too), the
# course's. Too long for CI's 10 minutes (about 4 minutes of build and 3 of tests per
# configuration on 2 idle cores), so it is run by hand and its last result stands in the README.
#   bash scripts/portability.sh                  every configuration below
#   bash scripts/portability.sh clang14-libc++   the named ones
# Configurations (build folder build-NAME/, each with its own ccache entries):
#   clang14-libc++   Debian's clang 14 with LLVM's libc++ 14: the closest to Apple clang we can run
#   clang14          clang 14 with GCC's libstdc++
#   clang19          clang 19 with libstdc++ and LLVM's OpenMP 19 (libomp): clang 19's OpenMP code
#                    calls __kmpc_dispatch_deinit, which libomp 14 lacks, and Debian 12's libomp 19
#                    packages conflict with the 14 packages that clang 14 needs. So libomp5-19 and
#                    libomp-19-dev (the version of the installed clang-19) are fetched with
#                    `apt-get download` and unpacked with `dpkg -x` into build-clang19/libomp19/,
#                    never installed; the build takes omp.h and libomp.so from there (rpath).
# Installs what is missing first (scripts/deps.sh --portability). A test that fails is run again
# once, alone (on a shared machine a test can run out of its time limit); the table at the end
# says which tests failed twice. Exit status 1 if a build or a test failed.
set -uo pipefail
cd "$(dirname "$0")/.."
all=(clang14-libc++ clang14 clang19)
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=("${all[@]}")
for c in "${configs[@]}"; do
  case " ${all[*]} " in *" $c "*) ;; *) echo "portability: unknown configuration '$c' (known: ${all[*]})" >&2; exit 2 ;; esac
done
bash scripts/deps.sh --portability || exit 1
export CCACHE_BASEDIR="$PWD"
# libomp5-19 and libomp-19-dev of the installed clang-19's version, unpacked into $1/root (not installed).
fetch_libomp19() {
  local dir=$1 ver d
  ver=$(dpkg-query -W -f='${Version}' clang-19) || return 1
  [ "$(cat "$dir/version" 2>/dev/null)" = "$ver" ] && return 0
  rm -rf "$dir" && mkdir -p "$dir/debs" || return 1
  (cd "$dir/debs" && apt-get download -q "libomp5-19=$ver" "libomp-19-dev=$ver") || return 1
  for d in "$dir"/debs/*.deb; do dpkg -x "$d" "$dir/root" || return 1; done
  echo "$ver" > "$dir/version"
}
jobs=$(nproc)
rows=() status=0
for c in "${configs[@]}"; do
  case "$c" in
    clang14*) cxx=clang++-14 ;;
    clang19*) cxx=clang++-19 ;;
  esac
  bld="build-$c"
  mkdir -p "$bld"
  flags=()
  [[ "$c" == *-libc++ ]] && flags=(-DCMAKE_CXX_FLAGS=-stdlib=libc++ -DCMAKE_EXE_LINKER_FLAGS=-stdlib=libc++
                                    -DCMAKE_SHARED_LINKER_FLAGS=-stdlib=libc++)
  if [ "$c" = clang19 ]; then  # OpenMP from Debian's libomp 19, unpacked into $bld/libomp19 (above)
    omp="$PWD/$bld/libomp19"
    if ! fetch_libomp19 "$omp" > "$bld/libomp19.log" 2>&1; then
      echo "portability: $c: could not fetch Debian's libomp 19 ($bld/libomp19.log):" >&2; cat "$bld/libomp19.log" >&2
      rows+=("| $c | $($cxx --version | head -1 | sed 's/ (.*//') | libomp 19 not fetched | | |"); status=1; continue
    fi
    lib="$omp/root/usr/lib/llvm-19/lib"
    link="-L$lib -Wl,-rpath,$lib"
    flags=("-DOpenMP_CXX_FLAGS=-fopenmp=libomp -isystem $lib/clang/19/include" -DOpenMP_CXX_LIB_NAMES=omp
           "-DOpenMP_omp_LIBRARY=$lib/libomp.so" "-DCMAKE_EXE_LINKER_FLAGS=$link"
           "-DCMAKE_SHARED_LINKER_FLAGS=$link")
  fi
  echo "portability: $c: $($cxx --version | head -1) in $bld/"
  t0=$SECONDS
  if ! cmake -S . -B "$bld" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" "${flags[@]}" \
      -DCMAKE_COMPILE_WARNING_AS_ERROR=ON -DCMAKE_CXX_COMPILER_LAUNCHER=ccache > "$bld/configure.log" 2>&1 ||
     ! cmake --build "$bld" -j"$jobs" > "$bld/build.log" 2>&1; then
    echo "portability: $c: the build failed (warnings are errors):" >&2
    grep -E "error|warning" "$bld/build.log" "$bld/configure.log" 2>/dev/null | head -20 >&2
    rows+=("| $c | $($cxx --version | head -1 | sed 's/ (.*//') | build failed ($bld/build.log) | | |")
    status=1
    continue
  fi
  built=$((SECONDS - t0)) t0=$SECONDS
  (cd "$bld" && ctest -j"$jobs" --timeout 300 > ctest.log 2>&1)
  total=$(sed -n 's/.* tests failed out of \([0-9]*\)$/\1/p' "$bld/ctest.log" | tail -1)
  failed=$(sed -n '/tests FAILED:/,$ s/^[[:space:]]*[0-9]* - \(.*\) ([^()]*)$/\1/p' "$bld/ctest.log")
  again=""
  if [ -n "$failed" ]; then
    (cd "$bld" && ctest --rerun-failed --timeout 300 > ctest-rerun.log 2>&1)
    again=$(sed -n '/tests FAILED:/,$ s/^[[:space:]]*[0-9]* - \(.*\) ([^()]*)$/\1/p' "$bld/ctest-rerun.log")
  fi
  tested=$((SECONDS - t0))
  nfail=0
  [ -n "$again" ] && nfail=$(printf '%s\n' "$again" | wc -l)
  graded=$(cd "$bld" && ctest -N -L '^lesson-' | sed -n 's/^Total Tests: //p')
  note="none"
  [ -n "$failed" ] && note="$(printf '%s\n' "$failed" | wc -l) failed, passed alone: $(printf '%s' "$failed" | paste -sd ';' -)"
  [ -n "$again" ] && { note="FAILED twice: $(printf '%s' "$again" | paste -sd ';' -)"; status=1; }
  rows+=("| $c | $($cxx --version | head -1 | sed 's/ (.*//') | $built s | $((total - nfail)) / $total ($graded graded) in $tested s | $note |")
  echo "portability: $c: built in $built s, $((total - nfail)) of $total tests passed ($note)"
done
echo
echo "| configuration | compiler | build (-Werror) | tests passed | failures |"
echo "|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
exit $status
