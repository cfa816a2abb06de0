# Shared by the CLI regression scripts (source it after setting corlab and work):
# refused FIELD ARGS...: `corlab ARGS` exits 2 with one stderr line naming FIELD and nothing on
# stdout, within 20 s. fail MESSAGE: prints it and exits 1.
# SPDX-License-Identifier: BSD-3-Clause
fail() { echo "FAIL: $*"; exit 1; }
refused() {
  local field=$1; shift
  timeout 20 "$corlab" "$@" > "$work/out" 2> "$work/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$* -> exit $rc, expected 2: $(cat "$work/err")"
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "$* -> not one line: $(cat "$work/err")"
  grep -qF -- "$field" "$work/err" || fail "$* -> does not name $field: $(cat "$work/err")"
  grep -q "^corlab: error: " "$work/err" || fail "$* -> not an error line: $(cat "$work/err")"
  [ ! -s "$work/out" ] || fail "$* -> wrote to stdout"
}
