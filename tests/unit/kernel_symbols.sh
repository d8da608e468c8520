#!/usr/bin/env bash
# Chapter 07's AVX and AVX-512 kernels are compiled with their instruction sets; any inline
# function they emitted (a std:: or glm helper, an exception's constructor) could be chosen by the
# linker for the whole program and run on a processor without those instructions. So each such
# object file must define exactly one external symbol, its kernel function, and nothing weak.
# Usage: kernel_symbols.sh OBJECT...   (the objects of freezeray_ch07; others are ignored)
set -euo pipefail
checked=0
# ctest passes the target's objects as one argument separated by ';'.
objects=()
for argument in "$@"; do
  IFS=';' read -ra parts <<< "$argument"
  objects+=("${parts[@]}")
done
for object in "${objects[@]}"; do
  case "$object" in
    *packet_kernel_avx.cpp.o|*packet_kernel_avx512.cpp.o) ;;
    *) continue ;;
  esac
  checked=$((checked + 1))
  symbols=$(nm -C --defined-only -g "$object" | awk '{ $1 = ""; print substr($0, 2) }')
  count=$(printf '%s\n' "$symbols" | grep -c . || true)
  if [ "$count" -ne 1 ] || ! printf '%s\n' "$symbols" | grep -q '^T freezeray::ch07::intersect_packet_avx'; then
    echo "FAIL: $object defines other external symbols than its kernel function:" >&2
    printf '%s\n' "$symbols" >&2
    exit 1
  fi
  echo "ok: $(basename "$object"): $symbols"
done
if [ "$checked" -eq 0 ]; then
  echo "no AVX kernel objects in this build (not x86-64)"
  exit 77
fi
