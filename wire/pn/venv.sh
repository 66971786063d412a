#!/usr/bin/env bash
# The IO controller's Python: a venv in target/wire-venv with profinet-py
# pinned (GPL-3.0: it runs as a separate process, never linked into gsdc).
# Made when missing; prints the venv's python.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
venv="$root/target/wire-venv"
pin="profinet-py==0.6.6"
if ! "$venv/bin/python" -c 'import importlib.metadata as m, sys; sys.exit(m.version("profinet-py") != "0.6.6")' 2>/dev/null; then
  python=$(command -v python3.11 || command -v python3) || { echo "no python3 for the controller's venv" >&2; exit 2; }
  "$python" -m venv "$venv" >&2
  "$venv/bin/pip" install --quiet --disable-pip-version-check "$pin" >&2
fi
echo "$venv/bin/python"
