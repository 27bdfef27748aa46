"""docs/first-case.md: its blocks make up its final file, which validates and runs.

Oracles: the page itself (the line-by-line blocks, joined, are the whole file it shows), the
statics of the same case (the run starts from the steady state at 4 kn: its first top tension
and sled depth are the statics') and the statics at 6 kn (the sled rises towards that depth:
211 m at 4 kn, 142 m at 6 kn, 161 m after 90 s at 6 kn).
"""
import re
import warnings

import pytest

from helpers import ROOT

PAGE = ROOT / "docs" / "first-case.md"


def _blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", PAGE.read_text(encoding="utf-8"), re.S)


def test_the_blocks_make_up_the_whole_file():
    blocks = _blocks("yaml")
    assert len(blocks) == 8
    assert "".join(blocks[:-1]) == blocks[-1]


def test_the_whole_file_validates():
    from kanat.io import check_text

    assert [str(p) for p in check_text(_blocks("yaml")[-1], "first.yaml")] == []


@pytest.mark.slow
def test_the_whole_file_runs_from_its_steady_state_towards_the_next():
    import kanat

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = kanat.load_case(_blocks("yaml")[-1])
        ds = kanat.simulate(case)
        start = kanat.solve_statics(case)
        data = case.model_dump(mode="json", by_alias=True, exclude_unset=True)
        data["vessel"]["track"] = [{"straight": {"speed_kn": 6, "duration": 120}}]
        end = kanat.solve_statics(kanat.load_case(data))
    assert ds.attrs["status"] == "ok"
    top = ds["tension"].values[:, 0]
    assert top[0] == pytest.approx(start["tension"].values[0], rel=1e-3)    # measured: 2e-5
    depth = -ds["body_position"].values[:, 0, 2]
    first, final = -start["body_position"].values[0, 2], -end["body_position"].values[0, 2]
    assert depth[0] == pytest.approx(first, rel=1e-3)                        # measured: 2e-5
    assert final < first - 50                                                # 6 kn lifts the sled
    assert depth.min() > final - 1.0                                         # never above the 6 kn depth
    assert (first - depth[-1]) / (first - final) > 0.6                       # measured: 72 % of the way
    script = _blocks("python")[-1]
    assert 'kanat.load_case("first.yaml")' in script and "ds.tension.isel(node=0)" in script
