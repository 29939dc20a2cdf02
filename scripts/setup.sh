#!/usr/bin/env bash
# Installs what clinch needs on Debian 12 (as root), makes OpenBLAS the BLAS and LAPACK that
# SuiteSparse uses, and builds a Release build/clinch. Safe to run again: it installs only
# what is missing and rebuilds incrementally. matplotlib draws the plots of `clinch study` and
# `clinch report`; Chromium loads the report page in its test. libspectra-dev is the Lanczos
# eigensolver of *FREQUENCY steps. petsc-dev brings PETSc with hypre and
# MUMPS, and OpenMPI (mpirun included) under it; slepc-dev the eigensolver of *FREQUENCY steps
# run with PETSc.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake ninja-build pkg-config python3
          libeigen3-dev libspectra-dev libsuitesparse-dev libopenblas-dev libopenblas0-pthread
          libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libfmt-dev nlohmann-json3-dev
          libre2-dev petsc-dev slepc-dev libceres-dev
          python3-matplotlib chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Debian's reference BLAS makes CHOLMOD 5-10x slower: select OpenBLAS and check the choice.
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
for lib in libblas.so.3 liblapack.so.3; do
  openblas="/usr/lib/${arch}/openblas-pthread/${lib}"
  update-alternatives --set "${lib}-${arch}" "${openblas}" >/dev/null
  chosen=$(readlink -f "/usr/lib/${arch}/${lib}")
  case "$chosen" in
    *openblas*) ;;
    *) echo "setup: ${lib} resolves to ${chosen}, not OpenBLAS" >&2; exit 1 ;;
  esac
done
echo "setup: BLAS/LAPACK = OpenBLAS ($(readlink -f /usr/lib/${arch}/libblas.so.3))"

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
