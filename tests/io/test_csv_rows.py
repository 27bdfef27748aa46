"""The one CSV row reader (kanat.io.csv_rows) behind the motion, sea-state and RAO tables.

Every fault is an error naming the file, the line and the column; the three tables read the same
way (comments, units in the header, blank lines), checked on each table's own reader.
"""
import pytest

from kanat.io.csv_rows import Row, TableError, TableSpec, read_rows
from kanat.io.raos import read_raos
from kanat.io.sea_states import read_sea_states
from kanat.io.tables import read_motion_table

SPEC = TableSpec("test table", ("time", "surge", "name"), ("time",), "test.csv")


def write(folder, text, name="t.csv"):
    path = folder / name
    (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)
    return path


def test_rows_keep_their_line_numbers_and_cells(tmp_path):
    path = write(tmp_path, "# comment\n\ntime (s), Surge [m], name\n# another\n0, 1.5, a\n\n2,  -3e2 , b c\n")
    rows = read_rows(path, SPEC)
    assert [r.line for r in rows] == [5, 7]
    assert rows[1].cells == {"time": "2", "surge": "-3e2", "name": "b c"}
    assert [r.number("surge") for r in rows] == [1.5, -300.0]
    assert rows[0].number("heave", 7.0) == 7.0 and rows[0].text("name") == "a"


@pytest.mark.parametrize("text, message", [
    ("", "t.csv: empty; the first row names the columns (time, surge, name)"),
    ("# only a comment\n", "t.csv: empty"),
    ("time, sruge\n", "t.csv: unknown column 'sruge' (did you mean 'surge'?); columns: time, surge, name"),
    ("time, surge, time\n", "t.csv: column 'time' appears twice"),
    ("surge, name\n0, a\n", "t.csv: needs a 'time' column; the header row lacks the column(s) time"),
    ("root:x:0:0:root:/root\n", "t.csv: its first row is not a header of column names (column 1 is no column name)"),
    ("time, surge\n0, 1\n1, 2, 3\n", "t.csv, line 3: 3 values for 2 columns"),
    ("time\n" + "1" * 140_000 + "\n", "t.csv: not a CSV file (field larger than field limit"),
    (b"time\n\xff\xfe\n", "t.csv: not a text file (it is not UTF-8); a test table is a CSV file"),
])
def test_a_bad_table_is_refused_naming_file_and_line(tmp_path, text, message):
    with pytest.raises(TableError) as error:
        read_rows(write(tmp_path, text), TableSpec(**{**SPEC.__dict__, "max_rows": 10}))
    assert message in str(error.value)
    assert "root:" not in str(error.value)


@pytest.mark.parametrize("value, words", [
    ("abc", "'abc' is not a number"),
    ("nan", "'nan' is not a finite number"),
    ("-inf", "'-inf' is not a finite number"),
    ("1" * 40, None),
    ("x" * 40, "'" + "x" * 20 + "' is not a number"),
])
def test_a_bad_value_names_its_line_and_column_and_is_quoted_short(value, words):
    row = Row("t.csv", 12, {"surge": value})
    if words is None:
        assert row.number("surge") == float("1" * 40)
        return
    with pytest.raises(TableError) as error:
        row.number("surge")
    assert str(error.value) == f"t.csv, line 12, column surge: {words}"


def test_the_file_checks(tmp_path):
    with pytest.raises(TableError, match=r"'t.txt' is not a .csv file; a test table is a CSV file \(test.csv\)"):
        read_rows(write(tmp_path, "time\n0\n", "t.txt"), SPEC)
    (tmp_path / "dir.csv").mkdir()
    with pytest.raises(TableError, match="dir.csv: not a regular file"):
        read_rows(tmp_path / "dir.csv", SPEC)
    with pytest.raises(TableError, match=r"t.csv: 0 MiB, more than the 0 MiB a test table may hold"):
        read_rows(write(tmp_path, "time\n0\n"), TableSpec(**{**SPEC.__dict__, "max_bytes": 3}))
    with pytest.raises(TableError, match="t.csv: 3 rows, more than 2"):
        read_rows(write(tmp_path, "time\n0\n1\n2\n"), TableSpec(**{**SPEC.__dict__, "max_rows": 2}))
    with pytest.raises(FileNotFoundError):
        read_rows(tmp_path / "missing.csv", SPEC)


def test_the_three_tables_read_alike(tmp_path):
    """Comments, blank lines and units in the header in each table; the values as written."""
    motion = write(tmp_path, "# motion\ntime (s), heave [m]\n\n0, 0\n10, -1.5\n", "motion.csv")
    assert read_motion_table(motion) == [[0.0] * 7, [10.0, 0.0, 0.0, -1.5, 0.0, 0.0, 0.0]]
    seas = write(tmp_path, "# seas\nname, hs (m), tp (s), probability, duration (s)\n\nstorm, 6, 12, 0.5, 600\n",
                 "seas.csv")
    assert read_sea_states(seas) == [{"name": "storm", "hs": 6.0, "tp": 12.0, "gamma": 3.3, "heading_deg": 0.0,
                                      "probability": 0.5, "duration": 600.0}]
    raos = write(tmp_path, "# raos\nomega (rad/s), heading_deg, dof, amplitude, phase_deg\n\n0.5, 0, Heave, 1.2, 30\n",
                 "raos.csv")
    assert read_raos(raos) == [(0.5, 0.0, "heave", 1.2, 30.0)]


@pytest.mark.parametrize("reader, header", [
    (read_motion_table, "time, surge"),
    (read_sea_states, "name, hs, tp, probability, duration"),
    (read_raos, "omega, heading_deg, dof, amplitude, phase_deg"),
])
def test_each_table_names_file_line_and_column_of_a_bad_number(tmp_path, reader, header):
    columns = [c.strip() for c in header.split(",")]
    good = {"name": "a", "dof": "surge"}
    row = [good.get(c, "1") for c in columns]
    bad = [*row[:1], "x1", *row[2:]]
    path = write(tmp_path, f"{header}\n# note\n{', '.join(row)}\n{', '.join(bad)}\n", "table.csv")
    with pytest.raises(TableError) as error:
        reader(path)
    assert str(error.value) == f"table.csv, line 4, column {columns[1]}: 'x1' is not a number"
