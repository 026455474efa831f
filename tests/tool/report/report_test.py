"""The report's grouping and its reading of history records (src/tool/report/report.py), unit by
unit: which findings make one group, which groups are new in a run, which make one defect in the
ledger, the cards' order, and every way a history folder can be bad.
Usage: report_test.py REPORT_SCRIPT_FOLDER"""

import json
import os
import sys
import tempfile
import unittest

sys.path.insert(0, sys.argv.pop(1))
import report  # noqa: E402


def finding(group, cls="oracle_defect", query="obb_obb", case_file=None, what="w"):
    f = {"query": query, "class": cls, "group": group, "what": what}
    if case_file:
        f["case_file"] = case_file
    return f


def record(started, findings, run="campaign", name=None):
    return {"format": "crosscheck history", "version": 1, "run": run, "started": started, "queries": {},
            "findings": findings, "_file": name or started + ".json"}


class Grouping(unittest.TestCase):
    def test_findings_are_grouped_by_their_group_not_their_text(self):
        groups = report.groups_of(record("a", [finding("g1", what="x"), finding("g1", what="y"), finding("g2", what="x")]))
        self.assertEqual({g: len(f) for g, f in groups.items()}, {"g1": 2, "g2": 1})

    def test_a_finding_without_a_group_is_grouped_by_what_it_says(self):
        groups = report.groups_of(record("a", [{"query": "q", "class": "impl_bug", "what": "says miss"}]))
        self.assertEqual(list(groups), ["says miss"])

    def test_a_group_is_new_only_in_the_first_run_that_meets_it(self):
        runs = [record("1", [finding("A"), finding("B")]), record("2", [finding("B"), finding("C")]),
                record("3", [finding("A")]), record("4", [])]
        self.assertEqual(report.new_groups_per_run(runs), [["A", "B"], ["C"], [], []])

    def test_a_defect_is_its_group_without_features_and_margin(self):
        self.assertEqual(report.defect_of("obb_obb oracle_defect exact=miss fcl.OBBd::overlap:wrong:hit touching parallel 1e-12"),
                         "obb_obb oracle_defect exact=miss fcl.OBBd::overlap:wrong:hit")
        self.assertEqual(report.defect_of("tri_tri impl_bug exact=hit library:failed degenerate crash 1e5"),
                         "tri_tri impl_bug exact=hit library:failed")
        # A party's name that looks like a feature is kept.
        self.assertEqual(report.defect_of("q oracle_defect exact=hit p.touching:wrong:miss"),
                         "q oracle_defect exact=hit p.touching:wrong:miss")


class Ledger(unittest.TestCase):
    def test_groups_of_one_defect_over_runs_make_one_row(self):
        defect = "obb_obb oracle_defect exact=hit bullet.btBoxBoxDetector:wrong:miss"
        runs = [record("2026-12-01T00:00:00Z", [finding(defect + " 1e-3"), finding(defect + " 1e-3"),
                                                finding("obb_obb impl_bug exact=hit library:wrong:miss", cls="impl_bug")]),
                record("2026-12-02T00:00:00Z", [finding(defect + " touching")]),
                record("2026-12-03T00:00:00Z", [finding(defect + " 1e-7")])]
        known = [{"match": "btBoxBoxDetector", "link": "https://example.invalid/1", "note": "reported"}]
        ledger = report.ledger_of(runs, known)
        self.assertEqual(len(ledger), 1)  # the impl_bug is not another library's defect
        row = ledger[0]
        self.assertEqual(row["defect"], defect)
        self.assertEqual((row["first"], row["last"]), ("2026-12-01T00:00:00Z", "2026-12-03T00:00:00Z"))
        self.assertEqual((row["times"], row["groups"], row["findings"]), (3, 3, 4))
        self.assertEqual((row["link"], row["note"]), ("https://example.invalid/1", "reported"))

    def test_a_defect_no_known_entry_matches_has_no_link(self):
        row = report.ledger_of([record("1", [finding("q oracle_defect exact=hit p:wrong:miss")])], [])[0]
        self.assertIsNone(row["link"])


class Cards(unittest.TestCase):
    def test_the_worst_class_first_then_a_stored_case_then_the_most_met(self):
        groups = report.groups_of(record("1", [
            finding("defect, stored", case_file="a.json"),
            finding("defect, twice"), finding("defect, twice"),
            finding("bug", cls="impl_bug"),
            finding("crash", cls="oracle_crash"),
        ]))
        self.assertEqual(report.cards_order(list(groups), groups), ["bug", "crash", "defect, stored", "defect, twice"])


class Records(unittest.TestCase):
    def folder(self, files):
        folder = tempfile.mkdtemp()
        for name, text in files.items():
            with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                f.write(text if isinstance(text, str) else json.dumps(text))
        return folder

    def good(self, started, run="campaign"):
        r = record(started, [], run)
        del r["_file"]
        return r

    def test_records_are_read_in_the_order_they_started(self):
        folder = self.folder({"b.json": self.good("2026-12-01T00:00:00Z"), "a.json": self.good("2026-12-02T00:00:00Z", "fuzz"),
                              "notes.txt": "not a record, not read"})
        self.assertEqual([r["_file"] for r in report.load_records(folder)], ["b.json", "a.json"])

    def test_every_bad_record_is_named_with_the_place(self):
        cases = {
            "line 2 column 1": "{\n",
            "not a crosscheck history record": {"format": "something else"},
            "record version 2": dict(self.good("x"), version=2),
            '"findings" is missing or not a list': {k: v for k, v in self.good("x").items() if k != "findings"},
            '"queries" is missing or not a dict': dict(self.good("x"), queries=[]),
            '"started" is missing or not a str': dict(self.good("x"), started=5),
        }
        for says, text in cases.items():
            with self.subTest(says=says):
                folder = self.folder({"r.json": text})
                with self.assertRaises(report.BadInput) as raised:
                    report.load_records(folder)
                self.assertIn(os.path.join(folder, "r.json"), str(raised.exception))
                self.assertIn(says, str(raised.exception))

    def test_a_folder_without_records_is_bad_input(self):
        with self.assertRaises(report.BadInput):
            report.load_records(self.folder({}))


if __name__ == "__main__":
    unittest.main(verbosity=1)
