#!/usr/bin/env bash
# The load-time CPU check (src/core/cpu_check.cpp) must itself run on any x86-64: its object file
# may hold no VEX/EVEX-encoded instruction (every AVX instruction, and SSE ones when built for
# AVX), no ymm/zmm/mask register, and none of x86-64-v3's scalar additions. Fails if the
# file's -march=x86-64 stops winning over the library's -march. Usage: cpu_check_isa_test.sh OBJ
set -euo pipefail
obj=$1
listing=$(objdump -d --no-show-raw-insn "$obj")
grep -q check_cpu_at_load <<<"$listing" || { echo "FAIL: no check_cpu_at_load in $obj"; exit 1; }
# Field 2 of a disassembled line is "mnemonic operands".
bad=$(awk -F'\t' 'NF >= 2 { print $2 }' <<<"$listing" |
  grep -E '^(v[a-z0-9]+|k[a-z]+[bwdq]|andn|bextr|blsi|blsmsk|blsr|bzhi|lzcnt|movbe|mulx|pdep|pext|rorx|sarx|shlx|shrx)\b|%[yz]mm|%k[0-7]' ||
  true)
if [ -n "$bad" ]; then
  echo "FAIL: instructions beyond baseline x86-64 in $obj:"
  sort <<<"$bad" | uniq -c
  exit 1
fi
echo "ok: $(awk -F'\t' 'NF >= 2' <<<"$listing" | wc -l) instructions, all baseline x86-64"
