"""Writing and checking generated files, for ``gen_docs.py`` (and any later generator):
each generator makes ``{file name: text}`` and these keep its folder in step with it (bytes
in UTF-8, so the drift tests compare exactly what is committed)."""
from __future__ import annotations

from pathlib import Path

__all__ = ["write_files", "stale_files"]


def write_files(files: dict[str, str], out_dir: Path) -> list[Path]:
    """Write each ``{name: text}`` into ``out_dir``; the paths written."""
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for name, text in files.items():
        path = out_dir / name
        path.write_bytes(text.encode("utf-8"))
        written.append(path)
    return written


def stale_files(files: dict[str, str], out_dir: Path) -> list[str]:
    """The names of ``files`` that are missing from ``out_dir`` or differ from their text."""
    return [name for name, text in files.items()
            if not (out_dir / name).is_file()
            or (out_dir / name).read_bytes() != text.encode("utf-8")]
