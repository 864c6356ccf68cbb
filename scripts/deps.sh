#!/usr/bin/env bash
# Installs the Debian 12 packages softgl needs to build and test, when any is missing (apt-get, as root).
# Extra package names given as arguments are checked too; a name of another architecture (libassimp-dev:arm64)
# adds that architecture to dpkg first.
set -euo pipefail

packages=(g++ make cmake ninja-build pkg-config libglm-dev libassimp-dev libstb-dev libjpeg62-turbo-dev catch2 libcli11-dev libwebp-dev "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

architectures=()
for p in "${missing[@]}"; do
  case "$p" in
    *:*) arch=${p##*:}
      if [ "$arch" != "$(dpkg --print-architecture)" ] && ! dpkg --print-foreign-architectures | grep -qx "$arch" &&
        [[ " ${architectures[*]} " != *" $arch "* ]]; then architectures+=("$arch"); fi ;;
  esac
done

if [ "$(id -u)" -ne 0 ]; then
  echo "softgl: missing packages: ${missing[*]}" >&2
  for arch in "${architectures[@]}"; do echo "softgl: run as root: dpkg --add-architecture $arch" >&2; done
  echo "softgl: run this script as root, or: sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
for arch in "${architectures[@]}"; do
  echo "softgl: adding the $arch architecture to dpkg"
  dpkg --add-architecture "$arch"
done
echo "softgl: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
