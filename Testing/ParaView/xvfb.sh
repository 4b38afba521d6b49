# Sourced by the ParaView tests and benchmarks: starts an Xvfb of our own (Debian's pvbatch needs
# an X server even offscreen; -noreset: two ranks reconnecting while the server resets abort)
# on the first free display from :140, 1024x768 unless DEEPSHADOW_XVFB_SCREEN says otherwise,
# and sets `display` and `xvfb` (its pid) for the caller to export and to kill.
display=""
for n in $(seq 140 199); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then display=":$n"; break; fi
done
Xvfb "$display" -screen 0 "${DEEPSHADOW_XVFB_SCREEN:-1024x768}x24" -nolisten tcp -noreset >/dev/null 2>&1 &
xvfb=$!
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X${display#:}" ] && break; sleep 0.1; done
