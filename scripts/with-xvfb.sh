#!/usr/bin/env bash
# Runs a command against a private Xvfb server. Xvfb picks a free display number itself
# (-displayfd), so tests running in parallel never race for one as `xvfb-run -a` can.
set -euo pipefail
ready=$(mktemp)
# -noreset: ParaView opens and closes a probe connection at start-up; a resetting server would
# refuse the real connection that follows.
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$ready" 2>/dev/null &
server=$!
trap 'kill "$server" 2>/dev/null || true; rm -f "$ready"' EXIT
for _ in $(seq 200); do
  [ -s "$ready" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.05
done
display=$(head -n 1 "$ready" || true)
if [ -z "$display" ]; then
  echo "with-xvfb: Xvfb did not start (is the xvfb package installed?)" >&2
  exit 1
fi
DISPLAY=":$display" "$@"
