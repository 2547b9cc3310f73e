#!/usr/bin/env bash
# Installs what ncsdk needs to build and test, from Debian packages only (Debian 12).
#
# Idempotent: it checks every tool and header first and installs only what is missing. As root it
# runs apt-get itself; as another user it prints the exact command to run and exits with 1.
# Nothing is downloaded at configure or build time, so this is the only install step.
set -euo pipefail

# package|how to tell it is there (a command name, or an absolute path to a file it ships)
requirements=(
  "cmake|cmake"
  "g++|g++"
  "make|make"
  "catch2|/usr/include/catch2/catch.hpp"
  "libeigen3-dev|/usr/include/eigen3/Eigen/Core"
  "nlohmann-json3-dev|/usr/include/nlohmann/json.hpp"
  "libbenchmark-dev|/usr/include/benchmark/benchmark.h"
  "clang-format|clang-format"
  "chromium|chromium"
  "clang-14|clang++-14"
  "libfuzzer-14-dev|/usr/lib/llvm-14/lib/libFuzzer.a"
)

missing=()
for entry in "${requirements[@]}"; do
  package="${entry%%|*}"
  probe="${entry#*|}"
  if [[ "${probe}" == /* ]]; then
    [[ -e "${probe}" ]] || missing+=("${package}")
  else
    command -v "${probe}" > /dev/null 2>&1 || missing+=("${package}")
  fi
done

# CMake 3.25 or newer (Debian 12 ships 3.25.1).
if command -v cmake > /dev/null 2>&1; then
  version="$(cmake --version | head -n1 | awk '{print $3}')"
  if ! printf '3.25.0\n%s\n' "${version}" | sort -V -C; then
    echo "setup: cmake ${version} is older than 3.25; install a newer cmake" >&2
    exit 1
  fi
fi

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "setup: all dependencies present"
  exit 0
fi

command_line="apt-get update && apt-get install -y --no-install-recommends ${missing[*]}"
if [[ "$(id -u)" -ne 0 ]]; then
  echo "setup: missing packages: ${missing[*]}" >&2
  echo "setup: run as root:" >&2
  echo "  ${command_line}" >&2
  exit 1
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends "${missing[@]}"
echo "setup: all dependencies present"
