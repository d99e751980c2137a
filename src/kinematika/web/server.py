"""The page's server: the contract's JSON API over the one engine, and the static page.

Starlette (the small ASGI toolkit FastAPI is built on) serves it under uvicorn. Each
request is read with a size bound, checked (`requests`), and computed by the same functions
the command line prints (`kinematika.commands`) in a bounded pool of threads, off the event
loop, with a time bound; the answer is the bytes the CLI would print. See docs/app.md.
"""
from __future__ import annotations

import io
import json
import os
from dataclasses import dataclass, field
from importlib import resources
from typing import TYPE_CHECKING, Any, Callable, Optional

import anyio
from starlette.applications import Starlette
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import Request as HttpRequest
from starlette.responses import FileResponse, JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from .. import commands
from ..errors import KinematikaError, Said, speaking
from ..joints.capabilities import Coordinate
from ..languages import LANGS
from .. import limits
from .requests import Request, parse_body
from .warm import warmed

if TYPE_CHECKING:
    from ..sweep.result import SweepResult

ENDPOINTS = ("solve", "sweep", "simulate", "centres", "explain", "draw", "edit", "assemblies", "exercise",
             "build", "sketch", "convert")
STATIC = resources.files("kinematika.web") / "static"
EXAMPLES = resources.files("kinematika.web") / "examples"
CSP = ("default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
       "img-src 'self' data: blob:; frame-src 'self' blob: data: about:; object-src 'none'; "
       "base-uri 'none'; form-action 'none'; frame-ancestors 'none'")
SECURITY = {"Content-Security-Policy": CSP, "X-Content-Type-Options": "nosniff",
            "Referrer-Policy": "no-referrer", "Cache-Control": "no-store"}


@dataclass
class Start:
    """What the page opens with: the model named on the command line (read once, at start)."""

    text: str = ""
    fmt: str = "yaml"
    name: str = ""
    examples: dict[str, str] = field(default_factory=dict)


class Failure(Exception):
    """An answer other than 200: an HTTP status and the contract's error JSON (its message a
    key of the errors' catalogue and its arguments, said in the request's language)."""

    def __init__(self, status: int, kind: str, message: "str | Said", where: str = "", /, **args: Any) -> None:
        self.error = KinematikaError(kind, message, where, **args)
        super().__init__(self.error.said)
        self.status = status
        self.extra: dict[str, Any] = {}        # more of the answer beside the error (`partial` rows)

    @property
    def body(self) -> dict:
        """The contract's error JSON, in the language in use (and `extra`)."""
        return {**self.error.as_json(), **self.extra}


def bundled_examples() -> dict[str, str]:
    """The examples shipped with the package, by file name (read once, at start)."""
    if not EXAMPLES.is_dir():
        return {}
    return {f.name: f.read_text(encoding="utf-8") for f in sorted(EXAMPLES.iterdir(), key=str)
            if f.name.endswith((".yaml", ".yml", ".toml", ".json"))}


def create_app(start: Optional[Start] = None, hosts: Optional[list[str]] = None,
               workers: int = limits.SERVER_THREADS) -> Starlette:
    """The application: the page, its static files and the JSON API. `hosts`: the host names
    requests may be addressed to (a guard against DNS rebinding); None accepts any."""
    start = start if start is not None else Start(examples=bundled_examples())
    pool = anyio.CapacityLimiter(workers)
    cache = Answers(limits.ANSWER_CACHE_BYTES)

    async def page(_: HttpRequest) -> Response:
        return FileResponse(str(STATIC / "index.html"), headers=SECURITY)

    async def opening(_: HttpRequest) -> Response:
        return JSONResponse({"model": start.text, "format": start.fmt, "name": start.name,
                             "examples": list(start.examples)}, headers=SECURITY)

    async def example(request: HttpRequest) -> Response:
        name = request.path_params["name"]
        if name not in start.examples:
            with speaking(_asked(request.query_params.get("lang"))):
                return _failure(Failure(404, "usage", "no-example", "name", name=name))
        fmt = "toml" if name.endswith(".toml") else "yaml"
        return JSONResponse({"model": start.examples[name], "format": fmt, "name": name},
                            headers=SECURITY)

    def api(endpoint: str) -> Callable:
        async def handle(request: HttpRequest) -> Response:
            """The answer; its errors in the request's `lang` (the body's, else the query's)."""
            asked = request.query_params.get("lang")
            try:
                raw = await _read_body(request)
            except Failure as err:
                with speaking(_asked(asked)):
                    return _failure(err)
            with speaking(_language_of(raw) or _asked(asked)):
                return await answer(raw)

        async def answer(raw: bytes) -> Response:
            warmed()            # the first request imports the libraries, alone (see web/warm.py)
            try:
                req = parse_body(endpoint, raw)
                key = (endpoint, raw)
                kept = cache.get(key)
                if kept is not None:
                    status, media, body = kept
                else:
                    if pool.statistics().tasks_waiting >= limits.WAITING:
                        raise Failure(503, "limit", "server-busy")
                    with anyio.fail_after(limits.REQUEST_SECONDS):
                        status, media, body = await anyio.to_thread.run_sync(
                            _compute, req, limiter=pool, abandon_on_cancel=True)
                    if status == 200:
                        cache.put(key, (status, media, body))
            except KinematikaError as err:
                return _error(400, _answered(err))
            except Failure as err:
                return _failure(err)
            except TimeoutError:
                return _failure(Failure(503, "limit", "server-timeout", endpoint,
                                        seconds=float(limits.REQUEST_SECONDS)))
            return Response(body, status_code=status, media_type=media, headers=SECURITY)
        return handle

    async def palette(_: HttpRequest) -> Response:
        from .build import offered_questions
        from .palette import TOOLS

        questions = {about: offered_questions(about) for about in ("point", "body")}
        return JSONResponse({"tools": [t.public() for t in TOOLS], "questions": questions}, headers=SECURITY)

    async def strings(request: HttpRequest) -> Response:
        from .strings import page_strings

        try:
            return JSONResponse(page_strings(request.path_params["lang"]), headers=SECURITY)
        except KinematikaError as err:
            with speaking("en"):
                return _error(404, err.as_json())

    async def template(request: HttpRequest) -> Response:
        from .templates import NAMES, template

        name = request.path_params["name"]
        if name not in NAMES:
            asked = request.query_params.get("lang")
            with speaking(_asked(asked)):
                return _failure(Failure(404, "usage", "no-template", "name", name=name))
        return JSONResponse({"model": template(name, request.query_params.get("lang", "en")),
                             "format": "yaml", "name": name}, headers=SECURITY)

    async def help_page(request: HttpRequest) -> Response:
        from .help import page_html

        try:
            body = page_html(request.path_params.get("name", "model-format.md"))
        except KinematikaError as err:
            with speaking(_asked(request.query_params.get("lang"))):
                return _error(404, err.as_json())
        if isinstance(body, bytes):
            return Response(body, media_type="image/png", headers=SECURITY)
        return Response(body, media_type="text/html; charset=utf-8", headers=SECURITY)

    routes = [Route("/", page), Route("/api/start", opening),
              Route("/api/examples/{name}", example),
              Route("/api/palette", palette), Route("/api/strings/{lang}", strings),
              Route("/api/templates/{name}", template),
              Route("/help", help_page), Route("/docs/{name:path}", help_page),
              *[Route(f"/api/{e}", api(e), methods=["POST"]) for e in ENDPOINTS],
              Mount("/static", StaticFiles(directory=str(STATIC)), name="static")]
    middleware = [Middleware(TrustedHostMiddleware, allowed_hosts=hosts)] if hosts else []
    return Starlette(routes=routes, middleware=middleware)


ENVIRONMENT = "KINEMATIKA_APP"      # how `kinematika app --workers N` hands its start to workers


def from_environment() -> Starlette:
    """The application of a worker process of `kinematika app --workers N`: the start (the
    model read once by the parent) and the allowed host names come in `KINEMATIKA_APP`."""
    given = json.loads(os.environ.get(ENVIRONMENT, "{}"))
    start = Start(given.get("text", ""), given.get("fmt", "yaml"), given.get("name", ""),
                  bundled_examples())
    return create_app(start, hosts=given.get("hosts"), workers=given.get("threads", limits.SERVER_THREADS))


class Answers:
    """The answers to the last requests, by endpoint and body, up to `limit` bytes: an
    answer is a function of its request, and a class often asks the same one."""

    def __init__(self, limit: int) -> None:
        from collections import OrderedDict

        self.limit, self.size = limit, 0
        self.kept: OrderedDict = OrderedDict()

    def get(self, key: tuple) -> Optional[tuple]:
        """The kept answer (status, media type, body) to request `key` (endpoint, body), or
        None; a hit becomes the most recently used."""
        answer = self.kept.get(key)
        if answer is not None:
            self.kept.move_to_end(key)
        return answer

    def put(self, key: tuple, answer: tuple) -> None:
        """Keep `answer` for request `key`: one costing more than an eighth of the limit is not
        kept, and the least recently used go until the rest fit in `limit` bytes."""
        cost = len(answer[2]) + len(key[1])
        if cost > self.limit // 8 or key in self.kept:
            return
        self.kept[key] = answer
        self.size += cost
        while self.size > self.limit:
            old_key, old = self.kept.popitem(last=False)
            self.size -= len(old[2]) + len(old_key[1])


async def _read_body(request: HttpRequest) -> bytes:
    """The body, refused (413) past `limits.REQUEST_BYTES` bytes before more is read; a body
    that is not declared JSON is refused (415): browsers then ask before a cross-site post."""
    kind = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if kind != "application/json":
        raise Failure(415, "usage", "request-content-type", "request")
    declared = request.headers.get("content-length")
    if declared is not None and declared.isdigit() and int(declared) > limits.REQUEST_BYTES:
        raise _too_large(int(declared))
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limits.REQUEST_BYTES:
            raise _too_large(size)
        chunks.append(chunk)
    return b"".join(chunks)


def _too_large(size: int) -> Failure:
    return Failure(413, "syntax", "request-too-large", "request", size=size, limit=limits.REQUEST_BYTES)


def _asked(lang: Optional[str]) -> str:
    """The query's `lang` when it is one kinematika speaks, else English: a request is said
    in its own language, never in the server's locale."""
    return lang if lang in LANGS else "en"


def _language_of(raw: bytes) -> Optional[str]:
    """The `lang` a request's JSON body asks its messages in (checked later with the rest of
    the body), or None: errors found before the body is read (or in a body that is not
    JSON) are said in the language of the query's `lang`, else in English (`_asked`)."""
    try:
        lang = json.loads(raw.decode("utf-8")).get("lang")
    except (UnicodeDecodeError, ValueError, AttributeError):
        return None
    return lang if lang in LANGS else None


def _answered(err: KinematikaError) -> dict:
    """The error's JSON; a mechanism left free (`mobility-free`) also says its degrees of
    freedom and the independent conditions its drivers give (`dof`, `conditions`), so the page
    tells "add an input" from a real error in any language."""
    body = err.as_json()
    if err.said.key == "mobility-free":
        body["error"].update(dof=int(err.said.args["dof"]), conditions=int(err.said.args["conditions"]))
    return body


def _error(status: int, body: dict) -> Response:
    return Response(commands.json_text(body), status_code=status, media_type="application/json",
                    headers=SECURITY)


def _failure(err: Failure) -> Response:
    return _error(err.status, err.body)


JSON, HTML, CSV = "application/json", "text/html; charset=utf-8", "text/csv; charset=utf-8"


def _compute(req: Request) -> tuple[int, str, bytes]:
    """The answer to a checked request (in a worker thread): status, media type, body.
    Internal failures answer 500 with a short note, as the CLI does (never a traceback)."""
    try:
        with speaking(req.get("lang") or "en"):
            media, body = COMPUTE[req.endpoint](req)
    except (KinematikaError, Failure):
        raise
    except Exception as err:
        if os.environ.get("KINEMATIKA_DEBUG"):
            raise
        with speaking(req.get("lang") or "en"):
            message = str(Said("internal-error-page", detail=f"{type(err).__name__}: {err}"))
        return 500, JSON, commands.json_text({"error": {"kind": "internal", "message": message,
                                                        "where": ""}}).encode()
    return 200, media, body if isinstance(body, bytes) else body.encode("utf-8")


def _solve(req: Request) -> tuple[str, str]:
    return JSON, commands.json_text(commands.solve_data(req.model, req.get("symbolic") or None,
                                                        req.how))


def _centres(req: Request) -> tuple[str, str]:
    return JSON, commands.json_text(commands.centres_data(req.model, req.get("symbolic") or None,
                                                          req.how))


def _sweep(req: Request) -> tuple[str, str | bytes]:
    _, result = commands.sweep_run(req.model, req.get("joint"), req.get("by"), req.get("steps"),
                                   req.get("skip_bad"), how=req.how)
    return _rows(req, result)


def _rows(req: Request, result: SweepResult) -> tuple[str, str | bytes]:
    """A sweep's or a motion's rows as the request asks (`as: csv`), else as `--json` writes them."""
    if req.get("as") == "csv":
        out = io.StringIO(newline="")
        result.write_csv(out)
        return CSV, out.getvalue()
    return JSON, b"".join(result.json_chunks()) + b"\n"


def _simulate(req: Request) -> tuple[str, str | bytes]:
    """What `simulate --json` prints (or its CSV); a motion that stops early answers 400 with
    the error and, under `partial`, the rows before it (as `simulate --json` prints them)."""
    from ..simulate.run import SimulationStopped

    try:
        _, result = commands.simulate_run(req.model, req.get("time"), req.get("steps"), req.get("method"),
                                          how=req.how)
    except SimulationStopped as err:
        failure = Failure(400, err.kind, err.said, err.where)
        failure.extra["partial"] = json.loads(b"".join(err.result.json_chunks()))
        raise failure from None
    return _rows(req, result)


def _explain(req: Request) -> tuple[str, str]:
    return HTML, commands.explain_text(req.model, req.get("lang", "en"), "html",
                                       req.get("symbolic") or None, req.get("length_unit"), req.how)


def _draw(req: Request) -> tuple[str, Any]:
    from ..draw.lock import MATPLOTLIB      # the endpoints that draw take turns (matplotlib)

    with MATPLOTLIB:
        return _drawn(req)


def _drawn(req: Request) -> tuple[str, Any]:
    from ..draw import DrawOptions

    keys = ("velocities", "accelerations", "centres", "curvature", "labels", "points", "view",
            "width", "lang")
    options = DrawOptions(**{k: req.get(k) for k in keys})
    model = req.how.model(req.model)
    if req.get("as") == "data":
        from .scene_json import depth_twin, scene_data

        sol, scene = commands.solved_scene(model, options)
        twin = depth_twin(scene, sol, options) if scene.dim == 3 else None
        return JSON, commands.json_text({**scene_data(scene, twin, options, req.get("frame")),
                                          "input": _input(model)})
    scene = commands.draw_scene(model, options)
    from ..draw.figure import render, svg_text

    fig = render(scene, options)
    if req.get("as") == "svg":
        return "image/svg+xml", svg_text(fig)
    out = io.BytesIO()
    fig.savefig(out, format="png", dpi=110, facecolor="white")
    return "image/png", out.getvalue()


def _input(model: Any) -> Optional[dict[str, Any]]:
    """What the page's slider advances: the joint a sweep advances, and its unit; or, for a
    model whose motion is followed in time (`simulate`), the time ("unit": "s") over which
    and in how many steps; None if neither."""
    from ..simulate.run import needs_time
    from ..sweep.plan import swept_joint

    if needs_time(model):
        return _time_input(model)
    try:
        joint, _ = swept_joint(model, model.sweep.joint if model.sweep else None)
    except KinematikaError:
        return _time_input(model) if model.simulate is not None else None
    return {"joint": joint.id, "unit": "deg" if joint.kind.coordinate is Coordinate.ANGLE else "length"}


def _time_input(model: Any) -> Optional[dict[str, Any]]:
    """The page's slider over time: the model's `simulate` section (written in its symbols:
    at their `draw_at` numbers, as it is simulated), else `DEFAULT_TIME` s."""
    from ..simulate.clock import DEFAULT_STEPS, DEFAULT_TIME, make_clock
    from ..simulate.run import at_numbers

    try:
        clock = make_clock(at_numbers(model)[0], 0.0, None, None, DEFAULT_TIME)
    except KinematikaError:
        clock = make_clock(model, 0.0, DEFAULT_TIME, DEFAULT_STEPS)
    return {"joint": None, "unit": "s", "time": clock.duration, "steps": clock.steps}


def _edit(req: Request) -> tuple[str, str]:
    from .edit import move_point

    text = move_point(req.model, req.how.fmt or "yaml", req.get("point"), req.get("to"))
    return JSON, json.dumps({"model": text})


def _build(req: Request) -> tuple[str, str]:
    from .build import apply

    text, selected = apply(req.model, req.how.fmt or "yaml", req.get("op"), req.get("lang", "en"))
    return JSON, json.dumps({"model": text, "select": selected})


def _sketch(req: Request) -> tuple[str, str]:
    from .build import sketch

    return JSON, commands.json_text(sketch(req.model, req.how.fmt or "yaml"))


def _convert(req: Request) -> tuple[str, str]:
    from .document import convert

    return JSON, json.dumps({"model": convert(req.model, req.how.fmt or "yaml", req.get("to")),
                             "format": req.get("to")})


def _assemblies(req: Request) -> tuple[str, str]:
    return JSON, commands.json_text(commands.assemblies_data(req.model, req.how))


def _exercise(req: Request) -> tuple[str, str]:
    from .exercise_api import exercise_answer      # the page's exercise mode

    return JSON, commands.json_text(exercise_answer(req))


COMPUTE = {"solve": _solve, "centres": _centres, "sweep": _sweep, "simulate": _simulate, "explain": _explain,
           "draw": _draw, "edit": _edit, "assemblies": _assemblies, "exercise": _exercise,
           "build": _build, "sketch": _sketch, "convert": _convert}
