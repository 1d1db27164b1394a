"""One Xvfb display for a whole experiment, for programs that need an X server (VTK's GLX window).

An X server resets when its last client leaves, and a client connecting during the reset is
refused: VTK then aborts with "bad X server connection" (peer_vtk lost whole runs to it, with one
xvfb-run per worker and with one shared server alike). One server for the run, on a display it
picks itself (-displayfd), started with -noreset and stopped when the block ends, has no such
window.

    with x_server.display("1920x1080x24") as x:
        subprocess.run(command, env=x.env, check=True)
"""
import contextlib
import os
import shutil
import signal
import subprocess

START_TIMEOUT_S = 30


class XDisplay:
    """A running Xvfb: `env` is os.environ with DISPLAY set to it; `alive()` whether it still runs."""

    def __init__(self, server, number):
        self.server = server
        self.number = number
        self.env = dict(os.environ, DISPLAY=f":{number}")
        self.env.pop("WAYLAND_DISPLAY", None)

    def alive(self):
        return self.server.poll() is None


@contextlib.contextmanager
def display(screen="1920x1080x24"):
    """Starts `Xvfb -displayfd` with one screen of `screen` (WxHxDEPTH); yields its XDisplay;
    stops the server on exit."""
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        raise SystemExit("Xvfb not found (Debian package xvfb; scripts/install-deps.sh installs it)")
    read_end, write_end = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", screen, "-nolisten", "tcp", "-noreset"],
                              pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    os.close(write_end)
    try:
        with os.fdopen(read_end) as pipe:
            number = _read_display_number(pipe, server)
        yield XDisplay(server, number)
    finally:
        server.send_signal(signal.SIGTERM)
        try:
            server.wait(timeout=START_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()


def _read_display_number(pipe, server):
    """The display number Xvfb writes once it accepts connections; exits with Xvfb's own message
    when it stops first."""
    import select

    ready, _, _ = select.select([pipe], [], [], START_TIMEOUT_S)
    line = pipe.readline().strip() if ready else ""
    if not line.isdigit():
        server.kill()
        _, error = server.communicate()
        raise SystemExit(f"Xvfb did not start within {START_TIMEOUT_S} s: {error.decode(errors='replace').strip()[-500:]}")
    return int(line)
