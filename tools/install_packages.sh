#!/usr/bin/env bash
# Installs the Debian packages named that are not installed (apt-get, as root or through sudo),
# naming them first; a no-op when all are there.
# Usage: tools/install_packages.sh [--missing] [--updated] PACKAGE...
#   --missing  only print the missing ones
#   --updated  skip `apt-get update` (an earlier call in the same run made it)
set -euo pipefail
list=0 update=1
while [ $# -gt 0 ]; do
    case $1 in
        --missing) list=1; shift ;;
        --updated) update=0; shift ;;
        *) break ;;
    esac
done
missing=$(for p in "$@"; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q 'install ok installed' || echo "$p"
done)
if [ $list = 1 ]; then echo $missing; exit 0; fi
[ -z "$missing" ] && exit 0
echo "Installing:" $missing
sudo=$([ "$(id -u)" = 0 ] || echo sudo)
if [ $update = 1 ]; then $sudo apt-get update -qq; fi
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing > /dev/null
