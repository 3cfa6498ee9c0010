"""Rewrite the README's category count and table from the registry.

Usage: python scripts/readme_categories.py [README.md]
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import artipg


def main(path: str = "README.md") -> None:
    readme = Path(path)
    text = readme.read_text()
    cats = artipg.categories()
    n_sub = sum(len(artipg.get_category(c).subcategories) for c in cats)
    table = "| category | sub-categories |\n|---|---|\n" + "".join(
        f"| `{c}` | {', '.join(artipg.get_category(c).subcategories)} |\n" for c in cats)
    text = re.sub(r"\| category \| sub-categories \|\n\|---\|---\|\n(\| `.*\n)+", table, text)
    text = re.sub(r"(`artipg categories` lists the )\d+( categories)", rf"\g<1>{len(cats)}\2", text)
    text = re.sub(r"\n\d+ categories, \d+ sub-categories, each", f"\n{len(cats)} categories, {n_sub} sub-categories, each",
                  text)
    readme.write_text(text)
    print(f"{len(cats)} categories, {n_sub} sub-categories")


if __name__ == "__main__":
    main(*sys.argv[1:])
