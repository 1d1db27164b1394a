"""One Xvfb display for a whole experiment, for programs that need an X server (VTK's GLX window).

Starting a server per process (xvfb-run -a) raced with the previous server's shutdown: after a
few runs every new client aborted with "bad X server connection" while a stale lock or socket
was left behind. One server, started here on a display it picks itself (-displayfd) and stopped
when the block ends, has no such window.

    with x_server.display("1920x1080x24") as env:
        subprocess.run(command, env=env, check=True)
"""
import contextlib
import os
import shutil
import signal
import subprocess

START_TIMEOUT_S = 30


@contextlib.contextmanager
def display(screen="1920x1080x24"):
    """Starts `Xvfb -displayfd` with one screen of `screen` (WxHxDEPTH); yields os.environ with
    DISPLAY set to it; stops the server on exit."""
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        raise SystemExit("Xvfb not found (Debian package xvfb; scripts/install-deps.sh installs it)")
    read_end, write_end = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", screen, "-nolisten", "tcp"],
                              pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    os.close(write_end)
    try:
        with os.fdopen(read_end) as pipe:
            number = _read_display_number(pipe, server)
        env = dict(os.environ, DISPLAY=f":{number}")
        env.pop("WAYLAND_DISPLAY", None)
        yield env
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
