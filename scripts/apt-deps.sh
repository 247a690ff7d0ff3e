#!/usr/bin/env bash
# Install the Debian packages SPARK needs (headless EGL rendering for MuJoCo, chromium for browser tests,
# postgresql: the trace store's tests start a throwaway server), when run as root with apt.
set -euo pipefail
PKGS=(libegl1 libgl1-mesa-dri libegl-mesa0 chromium-headless-shell postgresql)
missing=()
for p in "${PKGS[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
  echo "installing Debian packages: ${missing[*]}"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
else
  echo "warning: missing Debian packages ${missing[*]} (run as root or: sudo apt-get install ${missing[*]})" >&2
fi
