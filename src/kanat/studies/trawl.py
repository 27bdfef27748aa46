"""Bezverkhyi's towed spread: tension statistics before and after the speed step
(:mod:`kanat.analysis.step_response`), the paper's findings as computed checks, and the
study that runs the cases (``kanat study trawl examples/trawl_*.yaml -o DIR``).

The three points of the paper's figures 1-3 (Bezverkhyi 2006, "Чисельні результати") are the tow
point (``tow`` cable, s = 0), the otter-board attachment (``bridle_port`` at the board) and
the buoy attachment (``buoy_line`` at the buoy). ``jerk_ratio`` compares the largest rise of
tension within a second after the step with the largest in steady waves before it.
"""
from __future__ import annotations

from pathlib import Path

from kanat import api
from kanat.analysis.step_response import PointStatistics, snap_counts, step_statistics, step_time, table

POINTS = (("tow point", "tow", 0), ("otter board", "bridle_port", -1), ("buoy", "buoy_line", -1))
JERK_FACTOR = 2.0       # a rise this many times the largest one in steady waves is a jerk
SLIGHTLY = 0.10         # "slightly above": within 10 % of the old mean


def _grows(s: PointStatistics) -> dict[str, bool]:
    return {"mean grows": s.after.mean > s.before.mean and s.settled.mean > s.before.mean,
            "range grows": s.after.range > s.before.range, "jerks": s.jerk_ratio > JERK_FACTOR}


def _figure1(tow, board, buoy) -> dict[str, bool]:
    """theory/lumped.md §7 (the paper's figure 1, and its general statement)."""
    out = {f"tow point: {k}": v for k, v in _grows(tow).items()}
    out.update({f"otter board: {k}": v for k, v in _grows(board).items()})
    rise, settle = buoy.transient.mean - buoy.before.mean, buoy.settled.mean - buoy.before.mean
    out["buoy: mean first rises strongly"] = rise > 2.0 * max(settle, 0.0) and rise > 0.05 * buoy.before.mean
    out["buoy: then settles slightly above"] = 0.0 < settle < SLIGHTLY * buoy.before.mean
    out["buoy: range grows"] = buoy.settled.range > buoy.before.range
    return out


def _figures23(tow, board, buoy, figure: int) -> dict[str, bool]:
    """The paper's statements on its figures 2 (following waves) and 3 (head waves of 8 s)."""
    out = {"tow point: mean grows": tow.settled.mean > tow.before.mean,
           "tow point: range grows" + (" strongly" if figure == 3 else ""):
               tow.settled.range > (2.0 if figure == 3 else 1.0) * tow.before.range,
           "otter board: mean grows slightly": 1.0 < board.settled.mean / board.before.mean < 1.0 + 2 * SLIGHTLY,
           "otter board: range falls markedly": board.settled.range < 0.75 * board.before.range}
    if figure == 3:
        out.update({"tow point: jerks": tow.jerk_ratio > JERK_FACTOR,
                    "otter board: jerks": board.jerk_ratio > JERK_FACTOR,
                    "buoy: mean falls slightly": 1.0 - SLIGHTLY < buoy.settled.mean / buoy.before.mean < 1.0,
                    "buoy: range grows": buoy.settled.range > buoy.before.range})
    else:
        out.update({"buoy: mean falls": buoy.settled.mean < buoy.before.mean,
                    "buoy: range grows slightly": 1.0 < buoy.settled.range / buoy.before.range < 1.0 + 2 * SLIGHTLY})
    return out


FIGURES = {"trawl-head-waves-5.6s-speed-1-to-4": 1, "trawl-following-waves-4.5s-speed-1-to-2": 2,
           "trawl-head-waves-8s-speed-1-to-2": 3}


def findings(stats: list[PointStatistics], figure: int = 1) -> dict[str, bool]:
    """The paper's findings on its ``figure`` (1, 2 or 3) as computed checks of ``stats``
    (tow point, otter board, buoy). Figure 1's are theory/lumped.md §7's: at the tow point and the otter
    board the mean tension and its range grow after the step, with jerks; at the buoy the
    mean first rises strongly, then settles slightly above its old value, while the range
    grows. Figures 2 and 3 (1 -> 2 m/s) state other trends at the otter board and the buoy."""
    tow, board, buoy = stats
    return _figure1(tow, board, buoy) if figure == 1 else _figures23(tow, board, buoy, figure)


def report(ds) -> str:
    """Table, snap events and findings of one result, as Markdown."""
    stats = step_statistics(ds, POINTS)
    figure = FIGURES.get(ds.attrs.get("case_name", ""), 1)
    lines = [f"## {ds.attrs.get('case_name', '')}: speed step at {step_time(ds):g} s (paper's figure {figure})",
             "", "Tension [kN]:", "", table(stats), ""]
    snaps = snap_counts(ds)
    lines.append("Slack -> taut events (before / after the step): "
                 + (", ".join(f"{c} {a} / {b}" for c, (a, b) in snaps.items()) or "none"))
    lines += ["", "Findings of the paper reproduced:", ""]
    lines += [f"- {name}: {'yes' if ok else 'NO'}" for name, ok in findings(stats, figure).items()]
    return "\n".join(lines) + "\n"


def run_cases(paths, out_dir, reuse: bool = False):
    """Run Bezverkhyi's cases (or reuse ``out_dir/<case>.nc``): ``[(path, result dataset, report text)]``."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    done = []
    for path in map(Path, paths):
        result = out_dir / f"{path.stem}.nc"
        if reuse and result.exists():
            ds = api.read_result(result)
        else:
            outcome = api.run(api.load_case(path), output=result)
            if not outcome.ok:
                done.append((path, outcome.dataset, outcome.text))
                continue
            ds = outcome.dataset
        done.append((path, ds, report(ds)))
    return done
