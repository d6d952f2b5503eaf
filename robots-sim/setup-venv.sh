#!/usr/bin/env bash
# Create robots-sim/.venv from requirements.txt, idempotently.
# Skips all work when the venv exists and requirements.txt (and pyproject.toml) are unchanged,
# detected through a hash stamp kept inside the venv. Installs kicnp_sim in editable mode.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
VENV="$HERE/.venv"
STAMP="$VENV/.requirements.sha256"
PY="${PYTHON:-python3}"
want="$(cat "$HERE/requirements.txt" "$HERE/pyproject.toml" | sha256sum | cut -d' ' -f1)"
if [[ -x "$VENV/bin/python" && -f "$STAMP" && "$(cat "$STAMP")" == "$want" ]]; then
  echo "setup-venv: $VENV is up to date" >&2
  exit 0
fi
if [[ ! -x "$VENV/bin/python" ]]; then
  "$PY" -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install --disable-pip-version-check -q -r "$HERE/requirements.txt"
"$VENV/bin/python" -m pip install --disable-pip-version-check -q --no-deps -e "$HERE"
echo "$want" > "$STAMP"
echo "setup-venv: $VENV ready" >&2
