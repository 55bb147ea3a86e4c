#!/usr/bin/env bash
# Builds the demo into dist/ (what an author copies to a static host) and serves it on 127.0.0.1 (a
# secure context, as WebGPU requires).
# PORT picks the port (default 8000, or the next free one).
set -euo pipefail
cd "$(dirname "$0")/.."

bash www/dist.sh
source www/need-deb.sh
command -v python3 >/dev/null || need_deb python3
port=$(python3 - "${PORT:-8000}" <<'PY'
import socket, sys
start = int(sys.argv[1])
for port in range(start, start + 100):
    with socket.socket() as s:
        try:
            s.bind(("127.0.0.1", port))
        except OSError:
            continue
        print(port)
        break
else:
    sys.exit(f"no free port from {start} to {start + 99}")
PY
)
echo
echo "  metaballs is served at  http://127.0.0.1:$port/"
echo "  example lecture page:   http://127.0.0.1:$port/www/examples/lecture.html"
echo "  (open it in a browser with WebGPU; Ctrl-C stops the server)"
echo
exec python3 -m http.server --bind 127.0.0.1 "$port" --directory dist
