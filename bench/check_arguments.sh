#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Every bench program answers --help at once and refuses a bad argument with
# a short message and exit code 2, instead of starting a long benchmark.
#   check_arguments.sh PROGRAM
set -uo pipefail
prog=$1
name=$(basename "$prog")
out=$(timeout 20 "$prog" --help 2>&1); rc=$?
[ $rc -eq 0 ] || { echo "FAIL: $name --help exited $rc"; exit 1; }
grep -q "usage" <<<"$out" || { echo "FAIL: $name --help printed no usage: $out"; exit 1; }
[ "$(wc -l <<<"$out")" -le 3 ] || { echo "FAIL: $name --help printed more than the usage: $out"; exit 1; }

out=$(timeout 20 "$prog" --no-such-flag 2>&1); rc=$?
[ $rc -eq 2 ] || { echo "FAIL: $name --no-such-flag exited $rc: $out"; exit 1; }
[ "$(wc -l <<<"$out")" -le 2 ] || { echo "FAIL: $name --no-such-flag printed more than two lines: $out"; exit 1; }

if [ "$name" = io_bench ]; then
  out=$(timeout 20 "$prog" 10 1 /nonexistent/dir 2>&1); rc=$?
  [ $rc -eq 2 ] || { echo "FAIL: io_bench with a missing DIR exited $rc: $out"; exit 1; }
  [ "$(wc -l <<<"$out")" -le 2 ] || { echo "FAIL: io_bench with a missing DIR printed: $out"; exit 1; }
fi
echo "ok: $name"
