"""`kinematika app`: the interactive page, served on this machine (see docs/app.md)."""
from __future__ import annotations

import ipaddress
import socket
import sys
import threading
import webbrowser
from pathlib import Path
from typing import Any, Optional

import typer

from ..errors import KinematikaError, Said, reason
from .app import MessagesOpt, app, guarded, messages
import contextlib

LOOPBACK = ("127.0.0.1", "localhost", "::1")


@app.command("app")
def serve(
    model: Optional[Path] = typer.Argument(None, help="the model file to open (.yaml, .toml or "
                                           ".json); without it, a bundled example",
                                           show_default=False),
    port: int = typer.Option(0, "--port", min=0, max=65535, help="the port (0: a free one)"),
    host: str = typer.Option("127.0.0.1", "--host", help="the address to serve on; anything "
                             "but 127.0.0.1 lets other machines use the page"),
    no_browser: bool = typer.Option(False, "--no-browser", help="do not open a browser"),
    workers: int = typer.Option(1, "--workers", min=1, max=16, help="server processes (a class: "
                                "one per core)"),
    lang: Optional[str] = MessagesOpt,
) -> None:
    """The interactive page: edit a model, see it move, its answers and explanation (the
    page's messages are in the page's language; `--lang` is this command's own)."""
    messages(lang)
    from ..web.server import bundled_examples, create_app

    start = guarded(False, lambda: _start(model))
    start.examples = bundled_examples()
    sock = guarded(False, lambda: _bind(host, port))
    local = host in LOOPBACK
    if not local:
        print(Said("warning-line", text=Said("serving-open", host=host, port=sock.getsockname()[1])),
              file=sys.stderr)
    url = f"http://{'127.0.0.1' if host in ('0.0.0.0', '::') else _url_host(host)}:{sock.getsockname()[1]}/"
    hosts = ["127.0.0.1", "localhost"] if local else None
    if workers == 1:
        _run(create_app(start, hosts=hosts), sock, url, not no_browser)
    else:
        _run_workers(start, hosts, workers, sock, url, not no_browser)


def _start(model: Optional[Path]):
    """The model named on the command line, read once (the only file the server reads)."""
    from ..model.files import FORMATS, read_bytes
    from ..web.server import Start

    if model is None:
        return Start()
    fmt = FORMATS.get(model.suffix.lower())
    if fmt is None:
        raise KinematikaError("syntax", "file-type-unknown", str(model), suffix=repr(model.suffix or '(none)'),
                              noun="model-file", suffixes=list(FORMATS))
    try:
        text = read_bytes(model, str(model)).decode("utf-8-sig")
    except UnicodeDecodeError as err:
        raise KinematikaError("syntax", "file-not-utf8", str(model), byte=err.start + 1) from None
    return Start(text=text, fmt=fmt, name=model.name)


def _bind(host: str, port: int) -> socket.socket:
    """A listening socket on host:port (port 0: a free one), or a `usage` error."""
    try:
        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        sock = socket.socket(family, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
        sock.listen(128)
    except OSError as err:
        raise KinematikaError("usage", "cannot-serve", "--port" if port else "--host", address=f"{host}:{port}",
                              reason=reason(err)) from None
    sock.set_inheritable(True)
    return sock


def _url_host(host: str) -> str:
    try:
        return f"[{host}]" if ipaddress.ip_address(host).version == 6 else host
    except ValueError:
        return host


# Seconds an idle connection is kept open (uvicorn's default is 5): a page (or the load
# test's client) that posts on a connection the server is closing at that moment gets a
# read error, and a browser does not retry a POST; a student who pauses 5 s between two
# changes would meet it. 75 s, as common front servers keep them.
KEEP_ALIVE = 75


def _run(application, sock: socket.socket, url: str, browser: bool) -> None:
    import uvicorn

    config = uvicorn.Config(application, log_level="warning", access_log=False,
                            timeout_graceful_shutdown=2, timeout_keep_alive=KEEP_ALIVE)
    _announce(url, browser)
    with contextlib.suppress(KeyboardInterrupt):
        uvicorn.Server(config).run(sockets=[sock])


def _run_workers(start, hosts: Optional[list[str]], workers: int, sock: socket.socket, url: str,
                 browser: bool) -> None:
    """`workers` processes serving one socket (uvicorn's supervisor); each builds the app
    from the start handed over in the environment (`web.server.from_environment`)."""
    import json
    import os

    import uvicorn
    from uvicorn.supervisors import Multiprocess

    from ..web.server import ENVIRONMENT

    os.environ[ENVIRONMENT] = json.dumps({"text": start.text, "fmt": start.fmt, "name": start.name,
                                         "hosts": hosts})
    import inspect

    # a busy worker is not a dead one; a keyword of newer uvicorns only, so that it is looked up
    # in the installed one's signature at run time (Any: no version's stubs know it statically)
    patience: dict[str, Any] = {"timeout_worker_healthcheck": 120}
    patience = patience if "timeout_worker_healthcheck" in inspect.signature(uvicorn.Config).parameters else {}
    config = uvicorn.Config("kinematika.web.server:from_environment", factory=True,
                            workers=workers, log_level="warning", access_log=False,
                            timeout_graceful_shutdown=2, timeout_keep_alive=KEEP_ALIVE, **patience)
    _announce(url, browser)
    older = "target" in inspect.signature(Multiprocess).parameters    # uvicorn before 0.36
    extra = {"target": uvicorn.Server(config).run} if older else {}
    with contextlib.suppress(KeyboardInterrupt):
        Multiprocess(config, sockets=[sock], **extra).run()


def _announce(url: str, browser: bool) -> None:
    print(f"kinematika: the page is at {url} (Ctrl+C to stop)", flush=True)
    if browser:
        threading.Timer(0.6, lambda: webbrowser.open(url)).start()
