#!/usr/bin/env bash
# ci/lib.sh waits for a busy apt (issue 31): with a lock held by another process it says who holds it and
# waits; it fails with a clear message after POLYMECH_APT_WAIT seconds, and goes on once the lock is free.
# Uses its own lock file (POLYMECH_APT_LOCKS), held with a POSIX lock as apt and dpkg hold theirs.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$tmp"' EXIT
lock="$tmp/lock-frontend"
: >"$lock"
python=/usr/bin/python3
[ -x "$python" ] || python=python3

# hold LOCK for $1 seconds in the background (fcntl lockf: a POSIX lock, like apt's)
hold() {
  "$python" -c 'import fcntl, sys, time
f = open(sys.argv[1], "w"); fcntl.lockf(f, fcntl.LOCK_EX); open(sys.argv[1] + ".held", "w").close(); time.sleep(float(sys.argv[2]))' "$lock" "$1" &
  for _ in $(seq 100); do [ -e "$lock.held" ] && break; sleep 0.05; done
  rm -f "$lock.held"
}

fail() { echo "FAIL: $*"; exit 1; }

# free: no wait, no message
out="$(POLYMECH_APT_LOCKS="$lock" bash -c "source '$root/ci/lib.sh'; apt_wait_for_lock" 2>&1)" || fail "a free lock was refused: $out"
[ -z "$out" ] || fail "a free lock printed: $out"

# held longer than the wait: fails, naming the holder and the variable that sets the wait
hold 30
holder=$!
out="$(POLYMECH_APT_LOCKS="$lock" POLYMECH_APT_WAIT=2 POLYMECH_APT_POLL=1 bash -c "source '$root/ci/lib.sh'; apt_wait_for_lock" 2>&1)" && fail "a held lock was not waited for: $out"
echo "$out"
grep -q "apt is busy: process $holder" <<<"$out" || fail "no 'apt is busy: process $holder' in: $out"
grep -q "still busy after 2 s" <<<"$out" || fail "no 'still busy after 2 s' in: $out"
grep -q "POLYMECH_APT_WAIT" <<<"$out" || fail "the message does not name POLYMECH_APT_WAIT: $out"
kill "$holder"; wait "$holder" 2>/dev/null

# held for 2 s with a wait of 20 s: waits, then goes on
hold 2
out="$(POLYMECH_APT_LOCKS="$lock" POLYMECH_APT_WAIT=20 POLYMECH_APT_POLL=1 bash -c "source '$root/ci/lib.sh'; apt_wait_for_lock" 2>&1)" || fail "a lock released after 2 s was not waited for: $out"
echo "$out"
grep -q "apt is free after" <<<"$out" || fail "no 'apt is free after' in: $out"
echo "apt lock waiting: OK"
