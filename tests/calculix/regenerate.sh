#!/bin/sh
# Rewrites each .dat.ref of this directory from a CalculiX run of its deck (the .ccx.inp variant
# where there is one). Needs ccx (apt-get install calculix-ccx).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for deck in rigid_body_equation mpc_link; do
  source=$here/$deck.inp
  [ -f "$here/$deck.ccx.inp" ] && source=$here/$deck.ccx.inp
  cp "$source" "$scratch/$deck.inp"
  (cd "$scratch" && ccx -i "$deck" > "$deck.ccx.log")
  cp "$scratch/$deck.dat" "$here/$deck.dat.ref"
  echo "$deck.dat.ref written"
done
