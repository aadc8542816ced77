"""The README's Python examples (after <!-- python-example --> and <!-- python-quickstart -->) run and
print what the README shows."""
import os
import subprocess
import sys

README = os.path.join(os.path.dirname(__file__), "..", "..", "README.md")


def blocks(marker="<!-- python-example -->"):
    text = open(README, encoding="utf-8").read()
    rest = text[text.index(marker):]
    code = rest[rest.index("```python\n") + len("```python\n"):]
    code, rest = code[:code.index("```\n")], code[code.index("```\n") + 4:]
    shown = rest[rest.index("```\n") + 4:]
    return code, shown[:shown.index("```\n")]


def test_readme_python_example_prints_what_the_readme_shows():
    code, shown = blocks()
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == shown.splitlines()


def test_readme_quick_start_prints_what_the_readme_shows():
    code, shown = blocks("<!-- python-quickstart -->")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == shown.splitlines()
