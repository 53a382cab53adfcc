#!/usr/bin/env bash
# Builds tests/consumer against rackopt the two ways a user would and checks
# what the programs print:
#  1. `cmake --install BUILD` into a scratch prefix, then find_package(rackopt):
#     the consumer's k_min and k_mean of problems/rack_railway.yaml must equal
#     what `rackopt stiffness --json` of the same build prints (to 1e-8, the
#     consumer prints 9 digits);
#  2. add_subdirectory(rackopt) with tests and benchmarks off by default:
#     only the two modules the program links are built.
#
#   tests/consumer/check_consumer.sh BUILD_DIR [SCRATCH_DIR]
# Exit 0 when both agree. Uses ccache when CMAKE_CXX_COMPILER_LAUNCHER says so.
set -euo pipefail
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(cd "$1" && pwd)
scratch=${2:-$(mktemp -d)}
mkdir -p "$scratch"
jobs=$(nproc 2>/dev/null || echo 2)

fail() { echo "check_consumer: $*" >&2; exit 1; }

# 1. The installed package.
rm -rf "$scratch/prefix" "$scratch/installed"
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
[ -f "$scratch/prefix/lib/cmake/rackopt/rackoptConfig.cmake" ] || \
  [ -n "$(find "$scratch/prefix" -name rackoptConfig.cmake)" ] || fail "no rackoptConfig.cmake installed"
[ -x "$scratch/prefix/bin/rackopt" ] || fail "the program was not installed"
cmake -S "$src/tests/consumer" -B "$scratch/installed" -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$scratch/installed" -j "$jobs" >/dev/null
out=$("$scratch/installed/consumer" "$src/problems/rack_railway.yaml")
echo "$out"
json=$("$build/rackopt" stiffness "$src/problems/rack_railway.yaml" --json --out "$scratch/stiffness" 2>/dev/null)
python3 - "$out" "$json" <<'PY' || fail "the installed consumer's numbers differ from rackopt's"
import json, sys
got = dict(line.split(" ", 1) for line in sys.argv[1].splitlines())
ref = json.loads(sys.argv[2])
for key in ("k_min", "k_mean"):
    if abs(float(got[key]) - ref[key]) > 1e-8 * abs(ref[key]):
        sys.exit(f"{key}: consumer {got[key]}, rackopt {ref[key]}")
if abs(float(got["min_stiffness"]) - ref["k_min"]) > 1e-8 * ref["k_min"]:
    sys.exit("min_stiffness is not the curve's k_min")
PY

# 2. add_subdirectory: a configure without GoogleTest or Google Benchmark
#    targets, and the two modules the program needs.
rm -rf "$scratch/subdirectory"
cmake -S "$src/tests/consumer" -B "$scratch/subdirectory" -DRACKOPT_SOURCE="$src" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$scratch/subdirectory" -j "$jobs" --target consumer_units >/dev/null
sub=$("$scratch/subdirectory/consumer_units")
echo "$sub"
grep -qx "module 0.036" <<<"$sub" || fail "subdirectory consumer: module"
grep -q "^refused: .*furlongs" <<<"$sub" || fail "subdirectory consumer: the bad unit was not refused"
# No test programs were even defined (GoogleTest was never looked for).
if grep -q "GTest_DIR" "$scratch/subdirectory/CMakeCache.txt" || [ -d "$scratch/subdirectory/rackopt/tests" ] ||
   grep -q "test_core" "$scratch/subdirectory/rackopt/Makefile" 2>/dev/null; then
  fail "add_subdirectory configured rackopt's tests"
fi
echo "check_consumer: the installed package and add_subdirectory both work"
