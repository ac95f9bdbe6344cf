#!/usr/bin/env bash
# Installs what adcs needs from Debian 12's packages, and nothing else.
# Idempotent and non-interactive: packages already present are not touched, and
# apt is only called when something is missing. Called by tools/run-tests.sh and
# tools/run-main.sh; safe to run by hand.
set -euo pipefail

# Package -> why we need it (one place; README refers here).
pkgs=(
  cmake                        # build system (3.25 on Debian 12)
  ninja-build                  # fast generator
  g++                          # host compiler
  libeigen3-dev                # Eigen 3.4: the only dependency of include/adcs
  libsundials-dev              # SUNDIALS 6.4 CVODE for the ground simulation harness
  libgtest-dev                 # GoogleTest 1.12
  libgmock-dev
  libbenchmark-dev             # Google Benchmark 1.7 for adcs-bench
  python3-matplotlib           # plots (run with /usr/bin/python3)
  python3-numpy
  gcc-arm-none-eabi            # Cortex-M7 compile check of every public header
  libnewlib-arm-none-eabi
  libstdc++-arm-none-eabi-newlib
  qemu-system-arm              # runs the Cortex-M7 replay programs (mps2-an500) from ctest
  clang-14                     # libFuzzer harnesses (-fsanitize=fuzzer) and the ASan+UBSan suite
  libclang-rt-14-dev           #   and their sanitizer runtimes
  libomp-14-dev                #   OpenMP for clang: SUNDIALS' CMake config requires it
  gcovr                        # coverage preset (lines of include/adcs)
  valgrind                     # callgrind instruction counts per step (tools/callgrind-counts.sh)
  libcli11-dev                 # adcs-sim's command line (CLI11 2.1)
  nlohmann-json3-dev           # adcs-sim's JSON outputs and inputs (nlohmann/json 3.11)
  libtomlplusplus-dev          # vehicle / scenario files (toml++ 3.3, examples/vehicles/*.toml)
  libhdf5-dev                  # Monte Carlo time-series envelopes, one file per campaign (HDF5 1.10)
  python3-h5py                 #   read by tools/plot.py and tools/report.py
  slurm-wlm                    # the single-node Slurm test of tools/slurm/ (ctest label slurm)
  munge                        #   Slurm's authentication daemon
)

missing=()
for p in "${pkgs[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-deps: all ${#pkgs[@]} packages present"
  exit 0
fi

echo "setup-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# --no-install-recommends keeps SUNDIALS' MPI/PETSc closure as small as Debian allows.
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup-deps: done"
