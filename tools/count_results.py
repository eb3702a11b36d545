#!/usr/bin/env python3
"""Counts test cases in JUnit XML results; prints failures (with their first message lines) and 'N passed, N failed'. Exit 1 if any failed
or if no test ran."""
import glob
import os
import sys
import xml.etree.ElementTree as ET

root = sys.argv[1]
line_only = "--line-only" in sys.argv
passed = failed = 0
for path in sorted(glob.glob(os.path.join(root, "**", "*.xml"), recursive=True)):
    try:
        tree = ET.parse(path)
    except ET.ParseError:
        failed += 1
        if not line_only:
            print(f"unreadable result file: {path}")
        continue
    cases = list(tree.iter("testcase"))
    if not cases and tree.getroot().get("errors", "0") not in ("0", ""):
        failed += 1
        if not line_only:
            print(f"FAILED (no test case ran): {path}")
    for case in cases:
        bad = case.find("failure") is not None or case.find("error") is not None
        if bad:
            failed += 1
            if not line_only:
                print(f"FAILED: {case.get('classname')}.{case.get('name')} ({os.path.basename(path)})")
                # What failed, as the test said it (the first lines: CI shows only this output).
                for node in list(case.iter("failure")) + list(case.iter("error")):
                    text = (node.get("message") or "") + "\n" + (node.text or "")
                    lines = [l for l in text.splitlines() if l.strip()]
                    for l in lines[:12]:
                        print(f"    {l[:300]}")
        elif case.find("skipped") is None:
            passed += 1
if line_only:
    print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed or passed == 0 else 0)
