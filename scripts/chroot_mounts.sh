# Sourced by meshlab_env.sh, debian_minbase.sh, test_newer_meshlab.sh and test_packages.sh:
# the kernel file systems a Debian environment (chroot) needs while something runs in it,
# mounted for that time only, and the mirror to make one from. A cached environment is never
# left with /dev bound into it, where deleting the cache would reach the machine's own device
# files.

# chroot_mount CHROOT [HOST_DIR...]: /proc, /sys, /dev, and each HOST_DIR at its own path.
chroot_mount() {
  local root="$1"; shift
  mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
  mountpoint -q "$root/sys" || mount -t sysfs sysfs "$root/sys"
  mountpoint -q "$root/dev" || { mount --rbind /dev "$root/dev" && mount --make-rslave "$root/dev"; }
  local dir
  for dir in "$@"; do
    mkdir -p "$root$dir"
    mountpoint -q "$root$dir" || mount --bind "$dir" "$root$dir"
  done
}

# chroot_unmount CHROOT [HOST_DIR...]: the reverse; quiet about what was not mounted.
chroot_unmount() {
  local root="$1"; shift
  local dir
  for dir in "$@" /dev /sys /proc; do
    mountpoint -q "$root$dir" && { umount -R "$root$dir" 2>/dev/null || umount -l "$root$dir"; }
  done
  return 0
}

# debian_mirror: the mirror the machine itself uses for Debian's packages.
debian_mirror() {
  local uri
  uri="$(grep -rhsoE '^URIs:[[:space:]]*http[^[:space:]]*debian/?$' /etc/apt/sources.list.d/ | head -1 | awk '{print $2}')"
  [ -n "$uri" ] || uri="$(grep -hsoE '^deb[[:space:]]+http[^[:space:]]*debian/?[[:space:]]' /etc/apt/sources.list | head -1 | awk '{print $2}')"
  echo "${uri:-http://deb.debian.org/debian}"
}
