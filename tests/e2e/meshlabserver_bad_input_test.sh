#!/usr/bin/env bash
# Bad input through meshlabserver and the shipped scripts, for every case that reaches our
# filters (MeshLab's own importers read the file first; see docs/files-and-parameters.md on those): each
# run fails (a non-zero exit status that is not a crash) with the filter's reason in the
# log, and writes nothing.
# usage: meshlabserver_bad_input_test.sh MESHLABSERVER SCRIPTS_DIR WORKDIR
set -euo pipefail
MESHLABSERVER="$1"; SCRIPTS="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BAD="$HERE/../data/bad_inputs"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"
fail() { echo "FAIL: $*"; exit 1; }

# expect_refusal LOG_TEXT SCRIPT INPUTS...: a failure that is not a crash, the text in the log,
# and no file besides the inputs and the log.
expect_refusal() {
  local text="$1" script="$2"; shift 2
  local before; before="$(ls)"
  local inputs=(); for f in "$@"; do inputs+=(-i "$f"); done
  set +e; xvfb-run -a "$MESHLABSERVER" "${inputs[@]}" -s "$script" >run.log 2>&1; local got=$?; set -e
  # meshlabserver exits 255 when a filter fails; 128 and more would be a signal (a crash).
  { [ "$got" -ne 0 ] && [ "$got" -lt 128 ] || [ "$got" = 255 ]; } \
    || { cat run.log; fail "meshlabserver on $* exited $got, expected a refusal"; }
  grep -qE "Problem with filter|Filter .* failed" run.log || { cat run.log; fail "no filter refused $*"; }
  grep -q -- "$text" run.log || { cat run.log; fail "the log for $* does not say '$text'"; }
  rm run.log
  [ "$(ls)" = "$before" ] || fail "a refused run on $* left files: $(ls)"
}

# A vertex line with a word where a number belongs: MeshLab's OBJ importer keeps the
# vertices before it; our filter refuses the two it gets, naming the dialog's parameter.
cp "$BAD/obj_vertex_garbage.obj" garbage.obj
expect_refusal "Too few points: 2 distinct points, at least 9 are needed (k nearest neighbours + 1). Lower 'Neighbours k (0 = automatic)'" \
  "$SCRIPTS/compute_curve_skeleton.mlx" garbage.obj

# A thousand copies of one point.
/usr/bin/python3 -c "print('\n'.join(['1.5 2.5 3.5'] * 1000))" > copies.xyz
expect_refusal "Too few points: 1 distinct points (1000 with duplicates)" "$SCRIPTS/compute_curve_skeleton.mlx" copies.xyz

# A torus 1e7 from the origin: MeshLab's floats merge its points; the reason and the way out.
/usr/bin/python3 "$HERE/make_ring.py" 0.3 --torus >/dev/null  # torus.ply, ring.ply, ring_cut.ply
/usr/bin/python3 - <<'PY'
lines = open("torus.ply").read().splitlines()
start = lines.index("end_header") + 1
count = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
with open("far.xyz", "w") as out:
    for l in lines[start:start + count]:
        x, y, z = map(float, l.split()[:3])
        out.write("%.3f %.3f %.3f\n" % (x + 1e7, y + 2e6, z))
PY
expect_refusal "lies 1e+07 from the origin.*single precision.*pcskeleton command-line tool" \
  "$SCRIPTS/compute_curve_skeleton.mlx" far.xyz

# Reconstruction from five points with a valid skeleton: the count and the minimum.
head -n "$(( $(grep -n end_header torus.ply | cut -d: -f1) ))" torus.ply \
  | sed 's/^element vertex .*/element vertex 5/' > five.ply
sed -n "$(( $(grep -n end_header torus.ply | cut -d: -f1) + 1 )),+4p" torus.ply >> five.ply
expect_refusal "has 5 distinct points at the grid's resolution (5 points in all); the surface needs at least 32" \
  "$SCRIPTS/reconstruct_from_skeleton.mlx" five.ply ring.ply
echo "meshlabserver bad input: OK"
