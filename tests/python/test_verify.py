"""vibrofric.verify: the claims catalogue as a list of dicts, the fields of `vibrofric verify
--format json`."""
import vibrofric

FIELDS = {"key", "id", "source", "statement", "method", "how", "criterion", "proof", "worst", "verdict",
          "certification", "certification_note", "scope",
          "fails_where", "corrected", "cases", "deviation", "deviation_unit", "corrected_deviation", "measured",
          "digits"}


def test_eq17_holds():
    (row,) = vibrofric.verify("eq17", digits=20)
    assert set(row) == FIELDS
    assert row["key"] == "eq17" and row["id"] == "Eq. 17" and row["source"] == "paper"
    assert row["verdict"] == "holds" and row["certification"] == "certified" and "rationals" in row["certification_note"]
    assert row["cases"] > 0 and row["digits"] == 20
    assert isinstance(row["deviation"], str) and float(row["deviation"]) < 1e-15
    assert row["corrected_deviation"] is None
    assert all(set(m) == {"name", "value", "fields"} and isinstance(m["fields"], dict) for m in row["measured"])


def test_eq24_fails_as_printed():
    (row,) = vibrofric.verify("eq24", digits=10)
    assert row["verdict"] == "fails" and row["certification"] == "certified"
    assert row["corrected"] and row["corrected_deviation"] is not None


def test_measured_fields_are_the_printed_parts():
    """eq24's per-p measurement prints "printed / self-similar"; its fields hold the two numbers."""
    (row,) = vibrofric.verify("eq24", digits=10)
    per_p = [m for m in row["measured"] if m["name"].startswith("p = ") and "printed" in m["name"]]
    assert len(per_p) == 7
    for m in per_p:
        assert list(m["fields"]) == ["printed", "self_similar"]
        assert m["value"] == m["fields"]["printed"] + " / " + m["fields"]["self_similar"]
        assert float(m["fields"]["self_similar"]) < 1e-8


def test_claim_keys():
    assert "eq17" in vibrofric.claims and "eq24" in vibrofric.claims
    assert vibrofric.catalogue[0] == "sine"


def test_same_fields_and_values_as_the_tool_json():
    """The dicts hold what `vibrofric verify --format json` prints, field for field and in its order
    (the module builds them from the checks; the tool writes JSON)."""
    import json
    import os
    import subprocess
    tool = os.environ["VIBROFRIC_TOOL"]
    out = subprocess.run([tool, "verify", "--claim", "eq24", "--digits", "10", "--format", "json"],
                         capture_output=True, text=True, check=True).stdout
    (want,) = json.loads(out)["claims"]
    (row,) = vibrofric.verify("eq24", digits=10)
    assert list(row)[:len(want)] == list(want)
    for name, value in want.items():
        assert row[name] == value, name
    assert row["digits"] == 10
