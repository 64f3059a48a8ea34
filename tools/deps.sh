#!/bin/sh
# tools/deps.sh TOOL...: makes sure each command is on PATH. As root on Debian it installs
# the packages that provide the missing ones; otherwise it prints the command and fails.
set -u
package_of() {
  case "$1" in
    busted) echo lua-busted ;;
    luacheck) echo lua-check ;;
    xvfb-run) echo "xvfb xauth libgl1-mesa-dri" ;;
    *) echo "$1" ;;
  esac
}
missing="" packages=""
for tool in "$@"; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    missing="$missing $tool"
    packages="$packages $(package_of "$tool")"
  fi
done
[ -z "$missing" ] && exit 0
echo "missing:$missing"
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "installing: apt-get install -y$packages"
  # shellcheck disable=SC2086
  (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $packages) \
    >/tmp/budge-apt.log 2>&1 || { tail -20 /tmp/budge-apt.log; echo "apt-get failed"; exit 2; }
else
  echo "install them first, as root on Debian:"
  echo "  apt-get update && apt-get install -y$packages"
  exit 2
fi
