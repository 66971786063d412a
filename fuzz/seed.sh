#!/usr/bin/env bash
# Seeds the fuzz corpora from the shipped descriptions, the invalid fixtures
# and ../shared/corpus (copied into fuzz/corpus/, which git ignores: the
# third-party files are never committed).
set -euo pipefail
cd "$(dirname "$0")"
mkdir -p corpus/description corpus/compile corpus/gsd corpus/gsdml
cp ../descriptions/*.toml ../tests/fixtures/invalid/*.toml corpus/description/
cp ../descriptions/*.toml ../tests/fixtures/valid/*.toml corpus/compile/
cp ../../shared/corpus/gsd/*.[gG][sS]? corpus/gsd/
cp ../../shared/corpus/gsdml/*.xml ../../shared/corpus/gsdml-invalid/*.xml corpus/gsdml/
# gsdc import: the corpus's GSD and GSDML files and what the shipped
# descriptions build.
mkdir -p corpus/import
cp ../../shared/corpus/gsd/*.[gG][sS]? ../../shared/corpus/gsdml/*.xml corpus/import/
cargo run --quiet --manifest-path ../Cargo.toml -- build ../descriptions/*.toml --out corpus/import-built >/dev/null
cp corpus/import-built/*.GSD corpus/import-built/*.xml corpus/import/
rm -rf corpus/import-built
# gsdc doc: the descriptions that load; gsdc decode: each with arguments,
# NUL after the description and after each argument but the last.
mkdir -p corpus/doc corpus/decode
cp ../descriptions/*.toml ../tests/fixtures/valid/*.toml corpus/doc/
seed_decode() {
    local name=$1 description=$2
    shift 2
    {
        cat "$description"
        for arg in "$@"; do printf '\0%s' "$arg"; done
    } > "corpus/decode/$name"
}
seed_decode md810dp-ppo1 ../descriptions/md810dp.toml --module PPO1 --direction out '10F0 0800 0000 0000 0000 0000'
seed_decode md810dp-ppo5-json ../descriptions/md810dp.toml --module PPO5 --direction in --format json '00 00 00 00 00 00 00 00 0000 0000 0000 0000 0000 0000 0000 0000 0000 0000 0000 0000'
seed_decode md810dp-diag ../descriptions/md810dp.toml --diag '03 00 34'
seed_decode md810dp-prm ../descriptions/md810dp.toml --prm "00 00 00 $(printf 'F0 %02X ' $(seq 0 29))"
seed_decode mv810-mapping ../descriptions/mv810-pnet02.toml --module 'PKW + 2 PZD' --direction in --mapping pzd_in=3 '01 02 00 03 2B 02 00 01 0461 1388'
seed_decode 9kdp1-ppo3 ../descriptions/9kdp1.toml --module PPO3 --direction out '0001 1000'
seed_decode gateway-diag ../descriptions/md810-gateway.toml --diag '04 01 02 23'
seed_decode gateway-module ../descriptions/md810-gateway.toml --module 'INPUT 4 words' --direction in '0001 0002 0003 0004'
seed_decode profidrive ../tests/fixtures/valid/profidrive.toml --module PPO1 --direction out '1000 0000 0000 0000 047E 0000'
