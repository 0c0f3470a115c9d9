#!/usr/bin/env bash
# Installs what slidewave needs from Debian 12 packages, only what is missing (idempotent).
# Works as root or through sudo. Usage: scripts/setup.sh [--latex] [--test] [--slurm] [--getfem]
# --test adds what only the tests use (scripts/test.sh passes it): ParaView's VTK for tests/paraview
# (~540 MB) and Chromium for the labelled browser test.
set -euo pipefail

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas-dev libfftw3-dev libhdf5-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy python3-h5py python3-matplotlib python3-scipy python3-pytest python3-jsonschema
  python3-pandas python3-yaml snakemake
  ffmpeg  # movies (figures/movie.py)
)
for option in "$@"; do
  case "$option" in
    --latex) packages+=(latexmk texlive-latex-recommended poppler-utils) ;;  # poppler: pdftoppm renders the paper in tests
    --test) packages+=(
        python3-paraview  # ParaView's VTK: vtkXdmfReader for tests/paraview (python3-vtk9 has no XDMF reader)
        chromium          # the report in a real browser (tests/browser, marker `browser`; tests/figures/test_page_width.py)
      ) ;;
    --slurm) packages+=(slurmctld slurmd slurm-client munge) ;;
    --getfem) packages+=(python3-getfem) ;;
    *) echo "setup.sh: unknown option $option (allowed: --latex --test --slurm --getfem)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
echo "setup.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
# Recommends are skipped: snakemake's pull in cloud SDKs that take minutes and are not used.
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
