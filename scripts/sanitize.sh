#!/usr/bin/env bash
# `make sanitize`: the whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer
# (GCC), leak checking on. Mesa's driver keeps allocations for the life of the process and
# is unloaded before LeakSanitizer looks, so those reports are suppressed by
# tests/sanitize/lsan.supp (by module), never by turning leak checking off. Any other report
# fails the run. BUILD_SANITIZE (default build-sanitize) is the build directory. -O1 -g1
# (line tables only) as the sanitizers' documentation advises: about half the compile time
# of -O2 -g, and every report still names file and line.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${BUILD_SANITIZE:-build-sanitize}
jobs=${JOBS:-$(nproc)}
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "$jobs"
# Mesa's DRI driver is dlclose()d by eglTerminate/glXDestroyContext; its one-time allocations
# (made under pthread_once at the first eglInitialize) are then reported from "<unknown
# module>", which no suppression can name. Preloading the driver keeps it mapped, so its
# frames keep their module name and lsan.supp matches them by module. The preload comes
# before libasan in the link order, hence verify_asan_link_order=0 (ASan's documented switch).
dri=/usr/lib/$(gcc -print-multiarch)/dri/swrast_dri.so
[ -f "$dri" ] || { echo "sanitize: $dri not found (Mesa's software driver, package libgl1-mesa-dri)" >&2; exit 1; }
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:verify_asan_link_order=0"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
xvfb-run -a -s '-screen 0 1280x800x24' env LD_PRELOAD="$dri" ctest --output-on-failure -j "$jobs" "$@"
