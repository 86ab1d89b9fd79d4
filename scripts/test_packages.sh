#!/usr/bin/env bash
# The Debian packages on a clean system: a minimal Debian of this machine's release
# (scripts/debian_minbase.sh, cached in /var/cache/pcskeleton and copied afresh for every
# run) gets them with `apt-get install ./*.deb` and nothing else of ours, then checks there
# what a user would do:
#   - MeshLab's own plugin loader loads both plugins (meshlabserver with MeshLab 2020.09,
#     meshlab-run with 2021+), and the shipped skeleton script runs through it on an example;
#   - `pcskeleton --version` says the packages' version, `man pcskeleton` exists, and a run
#     on an example gives the right skeleton;
#   - `import pcskeleton` and a skeleton from numpy;
#   - a 10-line C++ program built with find_package(pcskeleton) runs;
#   - `apt-get purge` leaves no file of ours behind.
# The check's own tools (xvfb for meshlabserver's OpenGL, cmake and g++ for the C++
# program) are installed after ours. Needs root (debootstrap, chroot).
# usage: scripts/test_packages.sh DEB_DIR [SUITE]   (the packages of scripts/make_packages.sh,
#        made on Debian SUITE: this machine's release by default; trixie's come from
#        scripts/test_debian13_native.sh)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEBS="$(cd "${1:?usage: $0 DEB_DIR}" && pwd)"
[ "$(id -u)" -eq 0 ] || { echo "test_packages.sh needs root (debootstrap, chroot): run it with sudo" >&2; exit 1; }
ls "$DEBS"/*.deb >/dev/null 2>&1 || { echo "no .deb in $DEBS: run scripts/make_packages.sh first" >&2; exit 1; }
SUITE="${2:-$(. /etc/os-release && echo "$VERSION_CODENAME")}"
ENV_DIR="${PCSKELETON_ENV_DIR:-/var/cache/pcskeleton}"
CLEAN="$ENV_DIR/$SUITE-clean" ARCHIVES="$ENV_DIR/$SUITE-archives"
log() { printf '[test_packages] %s\n' "$*" >&2; }

source "$ROOT/scripts/chroot_mounts.sh"
BASE="$(bash "$ROOT/scripts/debian_minbase.sh" "$SUITE")"

log "a fresh copy of the minimal Debian $SUITE in $CLEAN"
unmount_clean() { umount "$CLEAN/var/cache/apt/archives" 2>/dev/null || true; chroot_unmount "$CLEAN"; }
unmount_clean  # a killed run's binds (its /dev) must not be deleted with its copy
rm -rf "$CLEAN"
cp -a "$BASE" "$CLEAN"
mkdir -p "$ARCHIVES" "$CLEAN/var/cache/apt/archives" "$CLEAN/tmp/debs"
cp "$DEBS"/*.deb "$CLEAN/tmp/debs/"
cp -r "$ROOT/tests/package" "$CLEAN/tmp/cxx"
cp "$ROOT/tests/e2e/make_ring.py" "$CLEAN/tmp/"
cp /etc/resolv.conf "$CLEAN/etc/resolv.conf" 2>/dev/null || true
chroot_mount "$CLEAN"
mount --bind "$ARCHIVES" "$CLEAN/var/cache/apt/archives"  # downloads kept between runs
trap 'unmount_clean; rm -rf "$CLEAN"' EXIT

version="$(dpkg-deb -f "$(ls "$DEBS"/pcskeleton_*.deb | head -1)" Version)"
chroot "$CLEAN" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  DEBIAN_FRONTEND=noninteractive bash -euo pipefail -c '
  version="$1"
  fail() { echo "FAIL: $*"; exit 1; }
  step() { printf "[in a clean %s] %s\n" "$(. /etc/os-release && echo "$PRETTY_NAME")" "$*"; }
  apt-get update -qq
  step "apt-get install ./*.deb"
  cd /tmp/debs
  apt-get install -y -qq --no-install-recommends ./*.deb >/tmp/install.log 2>&1 || { cat /tmp/install.log; fail "apt-get install ./*.deb"; }
  ours="$(dpkg-query -W -f="\${Package}\n" pcskeleton python3-pcskeleton libpcskeleton-dev meshlab-pcskeleton)"
  dpkg -L $ours | sort -u >/tmp/our_paths
  apt-get install -y -qq --no-install-recommends xvfb xauth cmake make g++ >/tmp/tools.log 2>&1 || { cat /tmp/tools.log; fail "the check tools"; }
  cd /tmp

  step "pcskeleton --version, man page, a torus"
  [ "$(pcskeleton --version)" = "pcskeleton ${version%-*}" ] || fail "pcskeleton --version: $(pcskeleton --version), packages: $version"
  [ -f /usr/share/man/man1/pcskeleton.1.gz ] || fail "no man page"
  python3 /tmp/make_ring.py 0.25 --torus  # /tmp/torus.ply: 6000 points of a torus
  pcskeleton /tmp/torus.ply -o /tmp/cli.ply --report /tmp/cli.txt >/tmp/cli.log 2>&1 || { cat /tmp/cli.log; fail "pcskeleton on a torus"; }
  grep -q "1 cycle" /tmp/cli.txt || { cat /tmp/cli.txt; fail "the torus has no cycle"; }

  step "python3: import pcskeleton, a skeleton from numpy"
  python3 -c "
import numpy as np, pcskeleton
assert pcskeleton.__file__.startswith(\"/usr/lib/python3/dist-packages/\"), pcskeleton.__file__
assert pcskeleton.__version__ == \"${version%-*}\", pcskeleton.__version__
s = pcskeleton.skeletonize(pcskeleton.read_points(\"/tmp/torus.ply\"))
assert s.report[\"topology\"][\"cycles\"] == 1, s.report[\"text\"]"

  script=/usr/share/pcskeleton/scripts/compute_curve_skeleton.mlx
  if command -v meshlabserver >/dev/null; then  # MeshLab 2020.09: Qt names what it loads
    step "MeshLab loads both plugins; the shipped script runs through meshlabserver"
    QT_DEBUG_PLUGINS=1 xvfb-run -a meshlabserver -i /tmp/torus.ply -o /tmp/meshlab_out.ply -s "$script" \
      >/tmp/meshlab.log 2>&1 || { tail -40 /tmp/meshlab.log; fail "meshlabserver"; }
    for plugin in libfilter_pcskeleton libedit_skeleton; do
      grep -q "loaded library \".*/meshlab/plugins/$plugin.so\"" /tmp/meshlab.log \
        || { grep -i "skeleton" /tmp/meshlab.log | head; fail "MeshLab did not load $plugin"; }
    done
  else  # MeshLab 2021+: meshlab-run, from meshlab-pcskeleton, asks MeshLab'"'"'s plugin manager
    step "MeshLab loads both plugins; the shipped script runs through meshlab-run"
    meshlab-run --list-plugins >/tmp/plugins.txt 2>&1 || { cat /tmp/plugins.txt; fail "meshlab-run --list-plugins"; }
    for plugin in FilterPCSkeleton:libfilter_pcskeleton EditSkeleton:libedit_skeleton; do
      grep -q "^${plugin%%:*}	/usr/lib/.*/meshlab/plugins/${plugin#*:}.so" /tmp/plugins.txt \
        || { cat /tmp/plugins.txt; fail "MeshLab did not load ${plugin#*:}"; }
      grep -q "^${plugin%%:*}	.*	pcskeleton ${version%-*}\$" /tmp/plugins.txt \
        || { cat /tmp/plugins.txt; fail "${plugin%%:*}'"'"'s vendor in Plugin Info is not pcskeleton ${version%-*}"; }
    done
    xvfb-run -a meshlab-run -i /tmp/torus.ply -s "$script" >/tmp/meshlab.log 2>&1 || { tail -40 /tmp/meshlab.log; fail "meshlab-run"; }
  fi
  # The script writes the skeleton beside its input.
  python3 -c "
import pcskeleton
s = pcskeleton.read_skeleton(\"/tmp/torus_skeleton.ply\")
assert s.topology[\"cycles\"] == 1, s.topology" || { tail -30 /tmp/meshlab.log; fail "the script gave no one-cycle skeleton"; }

  step "a C++ program with find_package(pcskeleton)"
  cmake -S /tmp/cxx -B /tmp/cxx-build -DCMAKE_BUILD_TYPE=Release >/tmp/cxx.log 2>&1 && cmake --build /tmp/cxx-build >>/tmp/cxx.log 2>&1 \
    || { cat /tmp/cxx.log; fail "the C++ program"; }
  [ "$(/tmp/cxx-build/torus_skeleton)" = "pcskeleton ${version%-*}: cycles 1" ] || fail "the C++ program: $(/tmp/cxx-build/torus_skeleton)"

  step "apt-get purge leaves nothing of ours"
  apt-get purge -y -qq $ours >/tmp/purge.log 2>&1 || { cat /tmp/purge.log; fail "apt-get purge"; }
  left=""
  while read -r path; do
    [ -e "$path" ] || continue
    if [ -d "$path" ]; then
      # A directory of ours is one no other package owns; it must be gone.
      dpkg -S "$path" >/dev/null 2>&1 || left="$left $path"
    else
      left="$left $path"
    fi
  done </tmp/our_paths
  [ -z "$left" ] || fail "left behind:$left"
  step "all checks passed"
' _ "$version"
log "the packages pass on a clean Debian $SUITE"
