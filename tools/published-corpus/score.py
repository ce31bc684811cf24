#!/usr/bin/python3
"""Compare derivcheck verdicts with the 'expected' labels; print a table per kind and the ids
of every false accept, false refute, input error and crash/timeout."""
import json, sys
from collections import defaultdict, Counter
claims_f = sys.argv[1] if len(sys.argv) > 1 else 'published.jsonl'
res_f = sys.argv[2] if len(sys.argv) > 2 else 'results.jsonl'
claims = [json.loads(l) for l in open(claims_f) if l.strip()]
results = {}
for l in open(res_f):
    l = l.strip()
    if not l.startswith('{'): continue
    r = json.loads(l)
    if 'line' in r: results[r['line']] = r
cols = ['T->ok', 'T->REFUTED', 'T->undec', 'F->refuted', 'F->ACCEPTED', 'F->undec', 'errors']
tab = defaultdict(Counter); lists = defaultdict(list); reasons = Counter(); reason_ids = defaultdict(list)
for i, c in enumerate(claims, 1):
    r = results.get(i)
    k = c['kind']; exp = c['expected'] == 'true'
    if r is None:
        tab[k]['errors'] += 1; lists['missing result (crash?)'].append(c['id']); continue
    v = r.get('verdict')
    txt = (r.get('reason') or '') + ' ' + (r.get('detail') or '')
    if v == 'error':
        tab[k]['errors'] += 1; lists['input error'].append(c['id']); continue
    if v == 'undecided' and ('budget' in txt or 'crash' in txt):
        lists['budget/crash (undecided)'].append(c['id'])
    if v in ('proved', 'holds_numerically'):
        if exp: tab[k]['T->ok'] += 1
        else: tab[k]['F->ACCEPTED'] += 1; lists['FALSE ACCEPT'].append(c['id'])
    elif v == 'refuted':
        if exp: tab[k]['T->REFUTED'] += 1; lists['FALSE REFUTE'].append(c['id'])
        else: tab[k]['F->refuted'] += 1
    elif v == 'undecided':
        tab[k]['T->undec' if exp else 'F->undec'] += 1
        reasons[(r.get('reason') or '?')[:110]] += 1
        reason_ids[(r.get('reason') or '?')[:110]].append(c['id'])
    else:
        tab[k]['errors'] += 1; lists['unknown verdict ' + str(v)].append(c['id'])
kinds = ['limit', 'series', 'equal', 'antiderivative', 'solves_ode']
w = 14
print('| kind | n | ' + ' | '.join(cols) + ' |')
print('|---|---|' + '---|' * len(cols))
tot = Counter()
for k in kinds:
    n = sum(tab[k].values()); tot.update(tab[k])
    print(f'| {k} | {n} | ' + ' | '.join(str(tab[k][c]) for c in cols) + ' |')
print(f'| **total** | {sum(tot.values())} | ' + ' | '.join(str(tot[c]) for c in cols) + ' |')
print()
for name in ['FALSE ACCEPT', 'FALSE REFUTE', 'input error', 'missing result (crash?)', 'budget/crash (undecided)']:
    print(f'{name} ({len(lists[name])}): ' + ', '.join(lists[name]))
print()
print('undecided reasons (raw, most common first):')
for r, n in reasons.most_common(40):
    print(f'  {n:3d}  {r}   e.g. {", ".join(reason_ids[r][:2])}')
