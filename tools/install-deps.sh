#!/usr/bin/env bash
# Installs everything derivcheck needs to build, test, benchmark and compile its LaTeX,
# from Debian 12 packages only. Idempotent; needs root (or sudo) and apt.
# libjs-katex (with fonts-katex) is the KaTeX `derivcheck html` copies into its sites;
# chromium (headless) is the browser the html tests load the page in.
set -euo pipefail
pkgs=(g++ cmake make pkg-config
      libginac-dev libcln-dev libflint-arb-dev libeigen3-dev catch2 libboost-dev libbenchmark-dev
      nlohmann-json3-dev libcli11-dev gnuplot-nox parallel
      llvm-14-dev libsleef-dev
      texlive-latex-base texlive-latex-recommended texlive-pictures texlive-science poppler-utils
      libjs-katex fonts-katex chromium)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q >/dev/null
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
  echo "install-deps: installed ${#missing[@]} packages" >&2
fi
