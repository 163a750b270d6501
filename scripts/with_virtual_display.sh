#!/bin/sh
# with_virtual_display.sh COMMAND [ARGS...]: runs COMMAND on a fresh virtual X display (Xvfb) and
# exits with COMMAND's exit code.
#
# Used instead of xvfb-run, whose clean-up of its X authority folder once failed in CI and turned
# the viewer's expected exit code 2 into xvfb-run's own 5. Xvfb picks a free display number itself
# (-displayfd) and listens only on its local socket, so no authority file is needed.
set -u
[ $# -ge 1 ] || { echo "usage: with_virtual_display.sh COMMAND [ARGS...]" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "with_virtual_display.sh: Xvfb not found (apt-get install xvfb)" >&2; exit 127; }

work=$(mktemp -d "${TMPDIR:-/tmp}/lumina-xvfb.XXXXXX") || exit 1
fifo=$work/display
mkfifo "$fifo" || exit 1

Xvfb -displayfd 3 -screen 0 640x480x24 -nolisten tcp 3>"$fifo" 2>"$work/xvfb.log" &
xvfb=$!
# -displayfd writes the display number once the server accepts connections.
display=$(head -n 1 "$fifo")
if [ -z "$display" ]; then
    echo "with_virtual_display.sh: Xvfb did not start:" >&2
    cat "$work/xvfb.log" >&2
    rm -rf "$work"
    exit 1
fi

DISPLAY=:$display "$@"
rc=$?

kill "$xvfb" 2>/dev/null
wait "$xvfb" 2>/dev/null
rm -rf "$work"
exit $rc
