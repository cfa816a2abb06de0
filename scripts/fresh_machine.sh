#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Times the README's first command on a fresh Debian 12 machine, phase by phase (issue 43): a
# minimal Debian 12 made with debootstrap stands for the fresh machine, a clean clone of this
# repository is copied into it, and the phases that `make run` goes through run there in order,
# each timed (wall seconds): apt (make, then `make deps`), configure, build, first answer,
# reproduction (studies and report, the `corlab reproduce` of `make run`).
#
# Usage (root, network to Debian's registry):
#   scripts/fresh_machine.sh DIR [PHASES]
# DIR: where the fresh system is made (debootstrap --variant=minbase bookworm, if DIR has none);
# PHASES: a comma list of apt,configure,build,first-answer,reproduce (default: all). Each phase's
# time is appended to DIR/corlab-timings.tsv and printed. Timings mean something only on a quiet
# machine; say which CPU (the script prints lscpu's model name).
set -euo pipefail

root=${1:?usage: scripts/fresh_machine.sh DIR [PHASES]}
phases=${2:-apt,configure,build,first-answer,reproduce}
repo=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)

if [ ! -x "$root/usr/bin/apt-get" ]; then
  mirror=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
  debootstrap --variant=minbase bookworm "$root" ${mirror:+"$mirror"}
fi
if [ ! -d "$root/corlab" ]; then
  git clone --quiet --no-hardlinks "$repo" "$root/corlab"
  cp /etc/resolv.conf "$root/etc/resolv.conf"
fi
for fs in proc sys dev; do
  mountpoint -q "$root/$fs" || mount --bind "/$fs" "$root/$fs"
done
trap 'for fs in dev sys proc; do umount "$root/$fs" 2>/dev/null || true; done' EXIT

# Runs one phase's command in the fresh system and records its wall time [s].
timed() {
  local name=$1 command=$2 start end
  start=$(date +%s.%N)
  chroot "$root" /bin/bash -c "cd /corlab && $command"
  end=$(date +%s.%N)
  awk -v n="$name" -v a="$start" -v b="$end" 'BEGIN { printf "%s\t%.1f\n", n, b - a }' |
    tee -a "$root/corlab-timings.tsv"
}

lscpu | grep 'Model name' || true
IFS=, read -r -a wanted <<<"$phases"
for phase in "${wanted[@]}"; do
  case $phase in
    apt) timed apt "apt-get update -qq && apt-get install -y -qq make >/dev/null && make deps" ;;
    configure) timed configure "make configure" ;;
    build) timed build "make build" ;;
    first-answer) timed first-answer "make first-answer" ;;
    reproduce) timed reproduce "build/bin/corlab reproduce --preset paper --out out/report" ;;
    *) echo "fresh_machine.sh: phase '$phase' is not one of apt,configure,build,first-answer,reproduce" >&2
       exit 2 ;;
  esac
done
