#!/usr/bin/env bash
# Creates (once) and caches a minimal Debian SUITE (debootstrap --variant=minbase, from the
# mirror this machine uses) in $PCSKELETON_ENV_DIR (default /var/cache/pcskeleton), with
# its own release and its updates as apt sources: the clean system scripts/test_packages.sh
# copies afresh for every run. Idempotent: a second run checks a stamp and returns at once.
# Prints the environment's path on stdout. Needs root (debootstrap).
# usage: scripts/debian_minbase.sh SUITE   (bookworm, trixie, ...)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SUITE="${1:?usage: $0 SUITE}"
[ "$(id -u)" -eq 0 ] || { echo "debian_minbase.sh needs root (debootstrap): run it with sudo" >&2; exit 1; }
ENV_DIR="${PCSKELETON_ENV_DIR:-/var/cache/pcskeleton}"
BASE="$ENV_DIR/$SUITE-minbase"

if [ ! -f "$BASE/.pcskeleton-ready" ]; then
  source "$ROOT/scripts/chroot_mounts.sh"
  command -v debootstrap >/dev/null || { apt-get update -qq; apt-get install -y -qq debootstrap >/dev/null; }
  mirror="$(debian_mirror)"
  printf '[debian_minbase] creating a minimal Debian %s in %s from %s\n' "$SUITE" "$BASE" "$mirror" >&2
  rm -rf "$BASE"
  mkdir -p "$ENV_DIR"
  debootstrap --variant=minbase "$SUITE" "$BASE" "$mirror" >&2
  printf 'Types: deb\nURIs: %s\nSuites: %s %s-updates\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$mirror" "$SUITE" "$SUITE" >"$BASE/etc/apt/sources.list.d/debian.sources"
  rm -f "$BASE/etc/apt/sources.list"
  touch "$BASE/.pcskeleton-ready"
fi
echo "$BASE"
