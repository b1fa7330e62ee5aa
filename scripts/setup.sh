#!/usr/bin/env bash
# Installs what the tests need on a fresh machine: the npm packages, and a Chromium for the
# headless-browser tests (Debian's package when apt-get is there, else Playwright's own build).
set -euo pipefail
cd "$(dirname "$0")/.."

npm ci --loglevel=warn

if [ -x /usr/bin/chromium ] || [ -x /usr/bin/chromium-browser ]; then
  exit 0
fi
if command -v apt-get >/dev/null 2>&1; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update
  $sudo apt-get install -y --no-install-recommends chromium
else
  npx playwright install chromium
fi
