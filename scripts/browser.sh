#!/usr/bin/env bash
# Debian's Chromium for the page's browser tests (tests/web/test_page.py), when missing.
# Playwright drives it through executable_path; `playwright install` is not used.
set -euo pipefail
if command -v chromium >/dev/null 2>&1 || [ -x /usr/bin/chromium ]; then
  exit 0
fi
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "installing Debian's chromium for the browser tests" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/dev/null
  apt-get install -y -q chromium >/dev/null
else
  echo "chromium is missing: install it (sudo apt-get install chromium) to run the browser tests;" \
       "without it they are skipped" >&2
fi
