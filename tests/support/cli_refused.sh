# Shared by the CLI regression scripts (source it after setting corlab and work):
# refused FIELD ARGS...: `corlab ARGS` exits 2 with one stderr line naming FIELD (a fixed string)
# and nothing on stdout, within 20 s. refused_re PATTERN ARGS...: the same with the line matching
# "^corlab: error: .*PATTERN" (a basic regular expression). fail MESSAGE: prints it and exits 1.
# SPDX-License-Identifier: BSD-3-Clause
fail() { echo "FAIL: $*"; exit 1; }
refusal() {
  local mode=$1 field=$2; shift 2
  timeout 20 "$corlab" "$@" > "$work/out" 2> "$work/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$* -> exit $rc, expected 2: $(cat "$work/err")"
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "$* -> not one line: $(cat "$work/err")"
  if [ "$mode" = regex ]; then
    grep -q "^corlab: error: .*$field" "$work/err" || fail "$* -> does not name $field: $(cat "$work/err")"
  else
    grep -qF -- "$field" "$work/err" || fail "$* -> does not name $field: $(cat "$work/err")"
    grep -q "^corlab: error: " "$work/err" || fail "$* -> not an error line: $(cat "$work/err")"
  fi
  [ ! -s "$work/out" ] || fail "$* -> wrote to stdout"
}
refused() { refusal fixed "$@"; }
refused_re() { refusal regex "$@"; }
