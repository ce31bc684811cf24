#!/usr/bin/env python3
"""Measure the document reader against the labelled documents (tests/data/documents).

Usage: tools/measure-documents.py BINARY [DOCUMENT...]

Runs `BINARY check --json` on each document and compares every labelled relation of its
NAME.expect file (LINE LINK LABEL, see tests/data/documents/README.md) with the verdict the
checker reports at that line and link. Prints one table row per document and the calls that
matter most: a wrong row called proved (false accept) and a true row refuted (false refute).
Exit status 1 when there is a false accept or a false refute.
"""
import glob
import json
import os
import subprocess
import sys
import time


def expectations(path):
    out = {}
    with open(path) as f:
        for raw in f:
            line = raw.split('#', 1)[0].strip()
            if not line:
                continue
            parts = line.split()
            out[(int(parts[0]), int(parts[1]))] = parts[2]
    return out


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    binary = sys.argv[1]
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tests', 'data', 'documents')
    docs = sys.argv[2:] or sorted(glob.glob(os.path.join(here, '*.md')) + glob.glob(os.path.join(here, '*.tex')))
    docs = [d for d in docs if os.path.basename(d) != 'README.md']
    header = f"{'document':28} {'labelled':>8} {'read':>5} {'derived':>8} {'given':>6} {'refuted':>8} {'undec':>6}" \
             f" {'true->der':>9} {'wrong->ref':>10} {'FA':>3} {'FR':>3} {'seconds':>8}"
    print(header)
    bad = []
    totals = {}
    for doc in docs:
        exp_path = os.path.splitext(doc)[0] + '.expect'
        if not os.path.exists(exp_path):
            continue
        expect = expectations(exp_path)
        t0 = time.time()
        run = subprocess.run([binary, 'check', '--json', doc], capture_output=True, text=True)
        seconds = time.time() - t0
        try:
            report = json.loads(run.stdout)
        except json.JSONDecodeError:
            print(f"{os.path.basename(doc):28} no JSON (exit {run.returncode}): {run.stderr.strip()[:200]}")
            bad.append((doc, 'no report'))
            continue
        got = {}
        for f in report.get('files', []):
            for s in f.get('steps', []):
                if s.get('rule') == 'given' and s.get('justification', {}).get('rule') == 'given' and \
                        s.get('label', '').startswith('I'):
                    continue   # an inline given of the prose, not a displayed row
                got[(s['line'], s.get('link', 0))] = s['verdict']
        row = dict(labelled=len(expect), read=0, derived=0, given=0, refuted=0, undecided=0,
                   true_derived=0, true_total=0, wrong_refuted=0, wrong_total=0, fa=0, fr=0)
        for key, label in expect.items():
            verdict = got.get(key, got.get((key[0], 0)))   # a row not read reports link 0
            if verdict is None:
                bad.append((doc, f"line {key[0]} link {key[1]}: no verdict reported"))
                continue
            row['read'] += 1
            if verdict in ('proved', 'holds_numerically'):
                row['derived'] += 1
            elif verdict == 'premise':
                row['given'] += 1
            elif verdict == 'refuted':
                row['refuted'] += 1
            else:
                row['undecided'] += 1
            if label in ('derived', 'given', 'approx'):
                row['true_total'] += 1
                if verdict in ('proved', 'holds_numerically') or (label == 'given' and verdict == 'premise'):
                    row['true_derived'] += 1
                if verdict == 'refuted':
                    row['fr'] += 1
                    bad.append((doc, f"line {key[0]} link {key[1]}: FALSE REFUTE of a {label} row"))
            elif label == 'wrong':
                row['wrong_total'] += 1
                if verdict == 'refuted':
                    row['wrong_refuted'] += 1
                if verdict in ('proved', 'holds_numerically'):
                    row['fa'] += 1
                    bad.append((doc, f"line {key[0]} link {key[1]}: FALSE ACCEPT of a wrong row"))
        for k, v in row.items():
            totals[k] = totals.get(k, 0) + v
        totals['seconds'] = totals.get('seconds', 0) + seconds
        print(f"{os.path.basename(doc):28} {row['labelled']:8} {row['read']:5} {row['derived']:8} {row['given']:6}"
              f" {row['refuted']:8} {row['undecided']:6} {row['true_derived']:4}/{row['true_total']:<4}"
              f" {row['wrong_refuted']:5}/{row['wrong_total']:<4} {row['fa']:3} {row['fr']:3} {seconds:8.2f}")
    t = totals
    if t:
        print(f"{'total':28} {t['labelled']:8} {t['read']:5} {t['derived']:8} {t['given']:6} {t['refuted']:8}"
              f" {t['undecided']:6} {t['true_derived']:4}/{t['true_total']:<4} {t['wrong_refuted']:5}/{t['wrong_total']:<4}"
              f" {t['fa']:3} {t['fr']:3} {t['seconds']:8.2f}")
    for doc, what in bad:
        print(f"{os.path.basename(doc)}: {what}")
    return 1 if any('FALSE' in w for _, w in bad) else 0


if __name__ == '__main__':
    sys.exit(main())
