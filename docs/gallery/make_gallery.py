"""Render every example model to docs/gallery/NAME.png and write docs/gallery.md.

    .venv/bin/python docs/gallery/make_gallery.py

Each example is drawn as `kinematika draw` draws it by default (the vectors, centres and
curvature circles its questions ask for); a few get a second picture with more shown.
An example that cannot be drawn is listed with the reason instead of a picture.
"""
from __future__ import annotations

import sys
from pathlib import Path

from rich.progress import Progress

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
OUT = ROOT / "docs" / "gallery"
PAGE = ROOT / "docs" / "gallery.md"
DPI = 110
WIDTH = 7.5
CENTRES = {"centres": True}
EXTRAS = {   # example: [(suffix, options, what the picture adds)]
    "four_bar": [("centres", {"centres": True, "accelerations": True},
                  "every instant centre with its Aronhold–Kennedy lines, and the accelerations")],
    "slider_crank": [("centres", CENTRES, "every instant centre")],
    "quick_return": [("centres", {"centres": True, "accelerations": True},
                      "every instant centre (the ram's, far above, at the edge with its "
                      "coordinates), and the accelerations")],
    "seed_c5_1_4_epicyclic": [("centres", CENTRES, "every instant centre: those of the "
                               "sun, ring, carrier and frame all at O")],
    "seed_c5_2_1_tricycle": [("centres", CENTRES, "every instant centre: the normals to the "
                              "wheels' planes meet at the chassis' centre")],
    "seed_c5_2_2_articulated": [("centres", CENTRES, "every instant centre: each unit's "
                                 "centre on the normal to its wheels")],
    "watt_six_bar": [("centres", CENTRES, "every instant centre")],
}
SWEEPS = {   # example: what its sweep plot shows
    "quick_return": "the ram's slow and quick strokes and their time ratio",
    "four_bar": "the rocker's swing and the coupler's motion over a crank turn",
    "slider_crank": "the piston's position, velocity and acceleration over a crank turn",
}


def describe(path: Path) -> str:
    """The first sentence of the example's opening comment: what it shows."""
    words = []
    for line in path.read_text(encoding="utf-8").splitlines():
        text = line.lstrip("#").strip()
        if not line.startswith("#") or not text:
            break
        words.append(text)
    paragraph = " ".join(words)
    end = paragraph.find(". ")
    sentence = paragraph if end < 0 else paragraph[: end + 1]
    return sentence if len(sentence) <= 240 else sentence[:237].rsplit(" ", 1)[0] + " …"


def render(path: Path, name: str, options: dict) -> str:
    """Draw `path` to OUT/name.png; '' when drawn, else the reason it could not be."""
    from kinematika.draw import DrawOptions, draw
    from kinematika.draw.figure import save
    from kinematika.errors import KinematikaError

    try:
        fig = draw(path, options=DrawOptions(width=WIDTH, **options))
        save(fig, OUT / f"{name}.png", dpi=DPI)
    except KinematikaError as err:
        return f"{err.kind}: {err}"
    except Exception as err:
        return f"internal error: {type(err).__name__}: {err}"
    return ""


def plot(path: Path, name: str) -> str:
    """The sweep plot of `path` to OUT/name.png; '' when drawn, else why not."""
    from kinematika.api import as_model
    from kinematika.draw import plot_sweep
    from kinematika.errors import KinematikaError
    from kinematika.sweep import run_sweep

    try:
        model = as_model(path)
        plot_sweep(run_sweep(model), OUT / f"{name}.png", model)
    except KinematikaError as err:
        return f"{err.kind}: {err}"
    return ""


def entry(path: Path, title: str, image: str, command: str, text: str) -> list[str]:
    rel = path.relative_to(ROOT).as_posix()
    out = [f"### {title}", "", f"[`{rel}`](../{rel})" + (f" — {text}" if text else ""), ""]
    out += [f"`{command}`", "", f"![{title}](gallery/{image})", ""]
    return out


def main() -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    for old in OUT.glob("*.png"):
        old.unlink()
    models = sorted(EXAMPLES.glob("*.y*ml")) + sorted(EXAMPLES.glob("*.toml")) + \
        sorted(EXAMPLES.glob("*.json"))
    lines = ["# Gallery", "",
             "Every example in `examples/` as `kinematika draw` draws it (made by "
             "`docs/gallery/make_gallery.py`; see [figures.md](figures.md) for what the "
             "drawings show). Symbolic examples are drawn at the numbers their `draw_at` "
             "gives, stated under each picture; the answers stay formulas.", ""]
    skipped = []
    with Progress(transient=True) as bar:
        task = bar.add_task("drawing examples", total=len(models))
        for path in models:
            name = path.stem
            reason = render(path, name, {})
            if reason:
                skipped.append(f"- `{path.name}`: {reason}")
            else:
                lines += entry(path, _title(path), f"{name}.png",
                               f"kinematika draw examples/{path.name} -o {name}.png",
                               describe(path))
                for suffix, options, text in EXTRAS.get(name, []):
                    if not render(path, f"{name}-{suffix}", options):
                        flags = " ".join(f"--{k}" for k in options)
                        lines += entry(path, f"{_title(path)}: {suffix}", f"{name}-{suffix}.png",
                                       f"kinematika draw examples/{path.name} {flags} -o "
                                       f"{name}-{suffix}.png", text)
                if name in SWEEPS and not plot(path, f"{name}-sweep"):
                    lines += entry(path, f"{_title(path)}: sweep", f"{name}-sweep.png",
                                   f"kinematika sweep examples/{path.name} --plot "
                                   f"{name}-sweep.png", SWEEPS[name])
            bar.advance(task)
    if skipped:
        lines += ["## Not drawn", ""] + skipped + [""]
    PAGE.write_text("\n".join(lines), encoding="utf-8")
    drawn = len(models) - len(skipped)
    print(f"drew {drawn} of {len(models)} examples into {OUT.relative_to(ROOT)}; wrote "
          f"{PAGE.relative_to(ROOT)}")
    return 0


def _title(path: Path) -> str:
    from kinematika.api import as_model
    from kinematika.errors import KinematikaError

    try:
        return as_model(path).name
    except KinematikaError:
        return path.stem


if __name__ == "__main__":
    sys.exit(main())
