#!/usr/bin/env bash
# Optional: the Python peers that bench/peers/run.sh compares derivcheck with (Debian 12
# packages python3-sympy, python3-numpy, python3-scipy). Not needed to build or test derivcheck.
# Idempotent; needs root (or sudo) and apt.
set -euo pipefail
pkgs=(python3 python3-sympy python3-numpy python3-scipy)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q >/dev/null
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
  echo "install-peers: installed ${#missing[@]} packages" >&2
fi
