#!/usr/bin/env bash
# pcskeleton on many inputs: -O, --jobs, --summary; one bad file among eight does not stop
# the rest; a rerun skips what is done, --force redoes it; plans that would overwrite an
# input or name one file twice are refused before any work.
# usage: cli_batch_test.sh PCSKELETON WORKDIR
set -euo pipefail
PCSKELETON="$1"; WORK="$2"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
GRAPH="/usr/bin/python3 $HERE/skeleton_graph.py"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"
fail() { echo "FAIL: $*"; exit 1; }

# Seven tori of 1500 points (one cycle each), two of them named alike in two folders, and
# one file that is no point cloud.
mkdir -p scans a b
/usr/bin/python3 - <<'PY'
import math, random
def torus(path, seed):
    random.seed(seed)
    with open(path, "w") as out:
        for _ in range(1500):
            t, u = random.uniform(0, 2 * math.pi), random.uniform(0, 2 * math.pi)
            r = 1 + 0.25 * math.cos(u)
            out.write("%.6f %.6f %.6f\n" % (r * math.cos(t), r * math.sin(t), 0.25 * math.sin(u)))
for i in range(5):
    torus("scans/torus%d.xyz" % i, i)
torus("a/ring.xyz", 10)
torus("b/ring.xyz", 11)
open("scans/broken.xyz", "w").write("these are not\npoints at all\n")
PY

md5sum scans/* a/* b/* > inputs.md5
cat > check_summary.py <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 8, rows
assert list(rows[0]) == ["input", "points", "nodes", "cycles", "tips", "parts", "warnings", "seconds", "status",
                         "message"], list(rows[0])
expected = dict(arg.split("=") for arg in sys.argv[2:])
for status, count in expected.items():
    assert sum(r["status"] == status for r in rows) == int(count), (status, rows)
for r in rows:
    if r["status"] == "ok":
        assert r["points"] == "1500" and r["cycles"] == "1" and r["parts"] == "1" and float(r["seconds"]) > 0, r
    if r["input"].endswith("broken.xyz"):
        assert r["status"] == "failed" and "broken.xyz" in r["message"], r
    else:
        assert r["status"] != "failed", r
PY

status=0
"$PCSKELETON" scans a/ring.xyz b/ring.xyz -O out --jobs 2 --summary out/summary.csv 2>run1.log || status=$?
[ "$status" -eq 1 ] || { cat run1.log; fail "one failed input should give exit status 1, got $status"; }
grep -q "1 of 8 inputs failed" run1.log || { cat run1.log; fail "no list of failures"; }
grep -q "scans/broken.xyz: " run1.log || { cat run1.log; fail "the failed input is not named"; }
for name in torus0 torus1 torus2 torus3 torus4 a_ring b_ring; do
  [ -f "out/${name}_skeleton.ply" ] || { ls out; fail "no out/${name}_skeleton.ply"; }
  $GRAPH check "out/${name}_skeleton.ply" --cycles 1 --components 1
done
[ "$(ls out | wc -l)" -eq 8 ] || { ls out; fail "other files than 7 skeletons and the summary were written"; }

/usr/bin/python3 check_summary.py out/summary.csv ok=7 failed=1 || fail "the first run's summary"

# A rerun skips the seven done (their files untouched) and fails the broken one again.
md5sum out/*_skeleton.ply > before.md5
touch -d '2001-01-01' out/*_skeleton.ply
status=0
"$PCSKELETON" scans a/ring.xyz b/ring.xyz -O out --summary out/summary.csv 2>run2.log || status=$?
[ "$status" -eq 1 ] || { cat run2.log; fail "the rerun should still report the broken input"; }
/usr/bin/python3 check_summary.py out/summary.csv skipped=7 failed=1 || fail "the rerun's summary"
[ -z "$(find out -name '*_skeleton.ply' -newermt '2002-01-01')" ] || fail "the rerun rewrote a done input's skeleton"
md5sum -c --quiet before.md5 || fail "the rerun changed a skeleton"
grep -q "7 skipped" run2.log || { cat run2.log; fail "the rerun did not skip the 7 done inputs"; }

# --force redoes them: the same skeletons again (one thread each, as before).
"$PCSKELETON" scans/torus0.xyz scans/torus1.xyz -O out --force --jobs 1 2>run3.log
[ -n "$(find out -name 'torus0_skeleton.ply' -newermt '2002-01-01')" ] || fail "--force did not redo torus0"
grep -q "2 done, 0 failed, 0 skipped" run3.log || { cat run3.log; fail "--force should redo both inputs"; }
md5sum -c --quiet before.md5 || fail "a redone skeleton differs from the first run's"

# Other outputs by pattern, and refusals before any work (exit status 2, nothing written).
"$PCSKELETON" scans/torus0.xyz a/ring.xyz -O more --branches '{stem}_branches.csv' --report '{stem}.txt' 2>/dev/null
for f in torus0_skeleton.ply torus0_branches.csv torus0.txt ring_skeleton.ply ring_branches.csv ring.txt; do
  [ -f "more/$f" ] || { ls more; fail "no more/$f"; }
done
refused() {  # refused EXPECTED-WORDS ARGS...
  local words="$1"; shift
  local code=0
  "$PCSKELETON" "$@" 2>refusal.log || code=$?
  [ "$code" -eq 2 ] || { cat refusal.log; fail "'$*' should be refused (exit 2), got $code"; }
  grep -q -- "$words" refusal.log || { cat refusal.log; fail "'$*': the refusal does not say '$words'"; }
}
refused "add -O FOLDER" scans/torus0.xyz scans/torus1.xyz
refused "put {stem} in it" scans/torus0.xyz scans/torus1.xyz -O none --branches branches.csv
refused "which is an input" scans/torus0.xyz a/ring.xyz -O scans --contracted '{stem}.xyz'
refused "matches no file" 'scans/*.nothing' -O none
refused "--jobs expects" scans -O none --jobs 0
[ ! -e none ] || fail "a refused batch made its output folder"
md5sum -c --quiet inputs.md5 || fail "an input changed"

# A file that is no summary table is not replaced by one.
echo "my notes" > notes.csv
status=0
"$PCSKELETON" scans/torus0.xyz -O out --summary notes.csv 2>notes.log || status=$?
[ "$status" -eq 1 ] && grep -q "not a batch summary table" notes.log || { cat notes.log; fail "notes.csv was not protected"; }
[ "$(cat notes.csv)" = "my notes" ] || fail "notes.csv was overwritten"
echo "command-line batch: OK"
