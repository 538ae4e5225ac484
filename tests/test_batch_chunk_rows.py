"""JSON lines take chunks sized by their width (issue 17: memory flat for wide commands such as
forced-response); the output does not depend on where the chunks fall."""
import json
import random

from dyncalc import batch
from helpers import invoke


def test_chunk_rows_by_output_and_width():
    assert batch.chunk_rows(False, 5, None) == batch.CHUNK_ROWS
    assert batch.chunk_rows(False, 5, ["x"] * 40) == batch.CHUNK_ROWS  # CSV: by the command
    assert batch.chunk_rows(False, 5, None, batch.ForcedRows().csv_rows) == 8192
    assert batch.CoriolisRows().csv_rows == batch.CHUNK_ROWS
    assert batch.chunk_rows(True, 5, None) == batch.FIRST_JSON_ROWS
    assert batch.chunk_rows(True, 2, ["omega", "f", "T"]) == batch.CHUNK_CELLS // 5
    assert batch.chunk_rows(True, 1, []) == batch.FIRST_JSON_ROWS  # no results yet
    assert batch.chunk_rows(True, 5, ["r"] * 200) == batch.FIRST_JSON_ROWS  # the floor
    assert batch.chunk_rows(True, 1, ["r"]) == batch.CHUNK_ROWS  # the ceiling


def _rows(n):
    rng = random.Random(7)
    lines = ["k,m,zeta,F0,Omega"]
    for _ in range(n):
        lines.append(f"{rng.uniform(50, 500)!r},{rng.uniform(1, 5)!r},"
                     f"{rng.uniform(0.01, 0.3)!r},{rng.uniform(1, 10)!r},"
                     f"{rng.uniform(1, 30)!r}")
    return "\n".join(lines) + "\n"


def test_json_lines_are_the_same_in_one_chunk_and_in_many(tmp_path, monkeypatch):
    path = tmp_path / "rows.csv"
    path.write_text(_rows(5000))
    many = invoke("forced-response", "--batch", str(path), "--json")
    assert many.exit_code == 0, many.stderr
    monkeypatch.setattr(batch, "FIRST_JSON_ROWS", 16384)
    monkeypatch.setattr(batch, "CHUNK_CELLS", 10 ** 9)
    one = invoke("forced-response", "--batch", str(path), "--json")
    assert one.exit_code == 0, one.stderr
    assert many.stdout == one.stdout
    lines = many.stdout.splitlines()
    assert [json.loads(line)["line"] for line in lines] == list(range(2, 5002))
    monkeypatch.undo()  # wide rows: the chunks after the first are smaller than CHUNK_ROWS
    width = 5 + len(json.loads(lines[0])["results"])
    assert batch.chunk_rows(True, 5, ["r"] * (width - 5)) < 5000
