#!/usr/bin/env bash
# Runs every shipped study with two rackopt binaries and checks that they
# give the same results: summary.json equal except its wall times (every
# "timings" object) and the output folder's path, and
# evaluations.csv (every recorded evaluation) byte for byte once the
# per-evaluation `seconds` column is dropped. For restructurings that must
# not change behaviour.
#
#   ./compare_studies.sh OLD_RACKOPT NEW_RACKOPT [STUDY.yaml ...]
#
# Example, the commit before a change against the working tree:
#   git worktree add /tmp/before HEAD~1 && cmake -S /tmp/before -B /tmp/before/build \
#     -DCMAKE_BUILD_TYPE=RelWithDebInfo && cmake --build /tmp/before/build --target rackopt_cli -j2
#   ./compare_studies.sh /tmp/before/build/rackopt build/rackopt
# Exit 0 when all agree, 1 when any differs (each difference is printed).
set -euo pipefail
if [ $# -lt 2 ]; then
  sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
old=$(realpath "$1"); new=$(realpath "$2"); shift 2
cd "$(dirname "$0")"
studies=("$@")
[ ${#studies[@]} -eq 0 ] && studies=(studies/*.yaml)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for s in "${studies[@]}"; do
  name=$(basename "$s" .yaml)
  for side in old new; do
    bin=$old; [ "$side" = new ] && bin=$new
    if ! "$bin" run "$s" --threads 1 --out "$work/$side/$name" > "$work/$side-$name.log" 2>&1; then
      echo "$name: the $side binary failed (exit $?), see its output:"; cat "$work/$side-$name.log"; status=1; continue 2
    fi
  done
  if python3 - "$work/old/$name" "$work/new/$name" <<'EOF'
import csv, io, json, sys
a, b = sys.argv[1], sys.argv[2]
def summary(d):
    # The output folder's own path is the one difference two runs must have.
    s = json.loads(open(d + "/summary.json").read().replace(d, "OUT"))
    def drop_timings(x):  # wall times, at any depth
        if isinstance(x, dict):
            return {k: drop_timings(v) for k, v in x.items() if k != "timings"}
        if isinstance(x, list):
            return [drop_timings(v) for v in x]
        return x
    return drop_timings(s)
def records(d):
    rows = list(csv.reader(open(d + "/evaluations.csv", newline="")))
    # The wall time's column: "seconds_s" (before units in headers: "seconds").
    i = rows[0].index("seconds_s") if "seconds_s" in rows[0] else rows[0].index("seconds")
    return [r[:i] + r[i + 1:] for r in rows]
ok = True
if summary(a) != summary(b):
    print("  summary.json differs"); ok = False
ra, rb = records(a), records(b)
if ra != rb:
    n = next((k for k, (x, y) in enumerate(zip(ra, rb)) if x != y), min(len(ra), len(rb)))
    print(f"  evaluations.csv differs: {len(ra)} vs {len(rb)} rows, first difference at row {n}")
    ok = False
sys.exit(0 if ok else 1)
EOF
  then
    echo "$name: same"
  else
    echo "$name: DIFFERENT"; status=1
  fi
done
exit $status
