#!/usr/bin/env bash
# The whole test suite: the command the README gives a new user, and the one
# .ci/run calls. It installs the system packages the tests need when they are
# missing: libxml2 and libclang for the PI schema validation in the tests;
# gcc, g++ and clang for the C layouts, which tests/c_header.rs compiles and
# runs; zip and unzip for the README's commands, which tests/docs.rs runs
# (unshare, of util-linux, checks the one that needs the network); Chromium
# and fonts with Latin and Chinese glyphs for the datasheet tests, which
# load each datasheet in a headless browser; for
# tests/output_safety.rs, which runs as root: mount (a read-only and a full
# tmpfs), e2fsprogs (chattr +i), util-linux (unshare --pid) and strace (a
# build killed in the middle of an fsync); iproute2 and Python's venv for
# the PROFINET exchange (tests/wire_pn.rs, as root), whose controller,
# profinet-py pinned, goes in a venv in target/wire-venv.
#
# With CI=true (.ci/run sets it) a test that still cannot run here fails
# instead of skipping: run this as root there.
set -euo pipefail
cd "$(dirname "$0")/.."

missing=()
for package in libclang-dev libxml2-dev libxml2-utils pkg-config gcc g++ clang zip unzip chromium fonts-liberation fonts-wqy-microhei mount e2fsprogs util-linux strace iproute2 python3-venv; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi

wire/pn/venv.sh >/dev/null

cargo test "$@"
