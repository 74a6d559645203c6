# SPDX-License-Identifier: Apache-2.0
# Sourced by tools/check-units (a build installed under a prefix) and tools/check-package (the
# installed .deb): the checks both run on raysd's units. Each expects the caller's fail() and $tmp.

# systemd-analyze verify SERVICE SOCKET. Exit status alone is not enough: verify exits 0 after
# "Unknown key" and "Failed to parse" warnings. Lines about other (host) units are shown but do not
# fail the check.
verify_units() {
  echo "== systemd-analyze verify"
  local verify_status=0
  systemd-analyze verify --man=no "$1" "$2" >"$tmp/verify.log" 2>&1 || verify_status=$?
  cat "$tmp/verify.log"
  [ "$verify_status" -eq 0 ] || fail "systemd-analyze verify exited with $verify_status"
  if grep -q 'raysd' "$tmp/verify.log"; then fail "systemd-analyze verify warned about the units"; fi
  [ "$verify_status" -eq 0 ] && [ ! -s "$tmp/verify.log" ] && echo "no warnings"
  return 0
}

# systemd-analyze security --offline=yes SERVICE, failing above MAX_EXPOSURE; prints the rating.
rate_service() {
  local service=$1 max_exposure=$2
  echo "== systemd-analyze security --offline=yes (at most $max_exposure)"
  # --threshold= takes the exposure times ten (3.5 is 35).
  local threshold security_status=0 exposure
  threshold=$(awk -v x="$max_exposure" 'BEGIN { printf "%d", x * 10 + 0.5 }')
  systemd-analyze security --offline=yes --threshold="$threshold" --no-pager "$service" \
    >"$tmp/security.log" 2>&1 || security_status=$?
  exposure=$(grep 'Overall exposure level' "$tmp/security.log" || true)
  if [ -z "$exposure" ]; then
    cat "$tmp/security.log" >&2
    fail "systemd-analyze security printed no exposure level"
  else
    echo "$exposure"
    [ "$security_status" -eq 0 ] || fail "exposure above $max_exposure (systemd-analyze security exited with $security_status)"
  fi
}
