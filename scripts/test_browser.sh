#!/usr/bin/env bash
# The viewer's browser test needs Chromium from the system's packages. Install it where
# apt-get can (Debian/Ubuntu, as root); elsewhere say so once: that test then skips.
if command -v chromium >/dev/null 2>&1 || command -v chromium-browser >/dev/null 2>&1; then
    exit 0
fi
if command -v apt-get >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium) >/dev/null 2>&1 \
        && exit 0
fi
echo "chromium not installed: the viewer's browser test will skip (install Debian's chromium to run it)"
