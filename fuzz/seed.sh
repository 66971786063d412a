#!/usr/bin/env bash
# Seeds the fuzz corpora from the shipped descriptions, the invalid fixtures
# and ../shared/corpus (copied into fuzz/corpus/, which git ignores: the
# third-party files are never committed).
set -euo pipefail
cd "$(dirname "$0")"
mkdir -p corpus/description corpus/compile corpus/gsd corpus/gsdml
cp ../descriptions/*.toml ../tests/fixtures/invalid/*.toml corpus/description/
cp ../descriptions/*.toml corpus/compile/
cp ../../shared/corpus/gsd/*.[gG][sS]? corpus/gsd/
cp ../../shared/corpus/gsdml/*.xml ../../shared/corpus/gsdml-invalid/*.xml corpus/gsdml/
