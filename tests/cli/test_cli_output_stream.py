"""The command line's output streams (kanat.cli_output.Stream) write what rich writes, without rich
where they can.

Oracle: rich itself. Every message is printed both by a Stream and by the rich console it stands
for (the same options, a file that is no terminal) and the two texts must be equal, character for
character; terminal detection is compared with rich's under the environment variables rich reads.
"""
import io
import os
import subprocess
import sys

import pytest
from rich.console import Console
from rich.text import Text

from kanat.cli_output import Stream

from helpers import EXAMPLES

MESSAGES = [
    "examples/speed_step_2d.yaml: valid (0 warning(s))",
    "case.yaml:12: cables[0].line_type: error: unknown line type 'wire' (did you mean 'wire2'?)",
    "",
    " leading and trailing spaces  ",
    "two\nlines",
    "ends with a line break\n",
    "\n\nblank lines first",
    "[bold red]markup[/] and [link=x]links[/link] stay as written",
    ":smile: :thumbs_up: emoji codes stay as written",
    "x" * 3000,                                                 # far past any width: one line
    "tension 1.2e+05 N at s = 0.5 m, 3 %, <0.1>, {'a': [1, 2]}",
    "unicode: θ = 45°, ± 1 µm, 温度 全角, combining é, emoji 🌊",
    # characters rich rewrites (tabs expanded, control codes stripped): the stream passes them to rich
    "a\ttab",
    "carriage\rreturn",
    "bell\x07 backspace\x08 form feed\x0c",
    "escape \x1b[31m sequence",
    "line\u2028separator",
]


def rich_text(message, **options):
    """What rich writes for ``message`` off a terminal (a StringIO)."""
    file = io.StringIO()
    Console(file=file, **options).print(message, markup=False, emoji=False)
    return file.getvalue()


@pytest.mark.parametrize("stderr", [False, True])
@pytest.mark.parametrize("message", MESSAGES, ids=range(len(MESSAGES)))
def test_a_message_off_a_terminal_is_what_rich_writes(monkeypatch, message, stderr):
    for name in ("FORCE_COLOR", "TTY_COMPATIBLE"):
        monkeypatch.delenv(name, raising=False)
    file = io.StringIO()
    monkeypatch.setattr(sys, "stderr" if stderr else "stdout", file)
    stream = Stream(stderr=stderr, soft_wrap=True, highlight=False)
    stream.print(message, markup=False, emoji=False)
    assert file.getvalue() == rich_text(message, soft_wrap=True, highlight=False)
    assert file.getvalue() == rich_text(Text(message), soft_wrap=True)   # print_problems' former form


def test_rich_is_built_only_for_what_plain_text_cannot_write(monkeypatch):
    monkeypatch.delenv("FORCE_COLOR", raising=False)
    monkeypatch.delenv("TTY_COMPATIBLE", raising=False)
    monkeypatch.setattr(sys, "stdout", io.StringIO())
    stream = Stream(soft_wrap=True)
    stream.print("plain", markup=False, emoji=False)
    assert (stream.is_terminal, stream._console) == (False, None)
    stream.print("a\ttab", markup=False, emoji=False)
    assert stream._console is not None
    assert sys.stdout.getvalue() == "plain\n" + "a" + " " * 7 + "tab\n"                 # rich's tab stops of 8


def test_quiet_prints_nothing_either_way(monkeypatch):
    monkeypatch.setattr(sys, "stdout", io.StringIO())
    stream = Stream(soft_wrap=True)
    stream.quiet = True
    stream.print("plain", markup=False, emoji=False)
    stream.print(Text("rich"))
    assert sys.stdout.getvalue() == "" and stream.rich.quiet


class FakeTerminal(io.StringIO):
    def isatty(self):
        return True


@pytest.mark.parametrize("environment", [{}, {"FORCE_COLOR": "1"}, {"FORCE_COLOR": ""}, {"TTY_COMPATIBLE": "0"},
                                         {"TTY_COMPATIBLE": "1"}, {"TTY_COMPATIBLE": "0", "FORCE_COLOR": "1"}])
@pytest.mark.parametrize("terminal", [False, True])
def test_terminal_detection_is_rich_s(monkeypatch, environment, terminal):
    for name in ("FORCE_COLOR", "TTY_COMPATIBLE"):
        monkeypatch.delenv(name, raising=False)
    for name, value in environment.items():
        monkeypatch.setenv(name, value)
    monkeypatch.setattr(sys, "stderr", FakeTerminal() if terminal else io.StringIO())
    assert Stream(stderr=True).is_terminal == Console(stderr=True).is_terminal


def test_validate_does_not_import_rich_off_a_terminal():
    """``kanat validate`` of a valid case in a pipe: its result line, and not one rich module."""
    script = ("import sys\nfrom kanat.cli import app\ntry:\n    app(sys.argv[1:])\nexcept SystemExit as end:\n"
              "    code = end.code\nprint(code, len([m for m in sys.modules if m.split('.')[0] == 'rich']))")
    case = EXAMPLES / "speed_step_2d.yaml"
    done = subprocess.run([sys.executable, "-c", script, "validate", str(case)], capture_output=True, text=True,
                          env={k: v for k, v in os.environ.items() if k != "FORCE_COLOR"})
    assert done.stdout.splitlines() == [f"{case}: valid (0 warning(s))", "0 0"], done.stderr


def test_show_prints_and_logs_the_plain_text_of_a_string_or_a_rich_text(monkeypatch, caplog):
    from kanat import cli_common

    cli_common.setup_logging()                    # the default: not quiet
    monkeypatch.setattr(sys, "stdout", io.StringIO())
    monkeypatch.setattr(cli_common.log, "propagate", True)
    with caplog.at_level("INFO", logger="kanat"):
        cli_common.show("wrote out.nc")
        cli_common.show(Text("pass  sphere-alpha0", style="green"))
    assert sys.stdout.getvalue() == "wrote out.nc\npass  sphere-alpha0\n"
    assert [r.getMessage() for r in caplog.records] == ["wrote out.nc", "pass  sphere-alpha0"]
