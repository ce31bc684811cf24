#!/usr/bin/env python3
"""Write a long Markdown document for timing the document reader (docs/documents.md).

Usage: tools/long-document.py OUT.md [COPIES]

Concatenates the seed handout (../shared/handout9.md) and every labelled Markdown test
document (tests/data/documents/*.md, tests/data/documents/heldout/*.md), each under a heading
of its own (their derivcheck declarations dropped: two documents may declare one name), COPIES
times (default 1). Prints the number of lines, characters and pages (3000
characters a page).
"""
import glob
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, '..')
docs = [os.path.join(root, '..', 'shared', 'handout9.md')]
docs += sorted(glob.glob(os.path.join(root, 'tests', 'data', 'documents', '*.md')))
docs += sorted(glob.glob(os.path.join(root, 'tests', 'data', 'documents', 'heldout', '*.md')))
docs = [d for d in docs if os.path.basename(d) != 'README.md']
copies = int(sys.argv[2]) if len(sys.argv) > 2 else 1
parts = []
for k in range(copies):
    for d in docs:
        text = open(d).read()
        # declarations are per document (two documents may declare the same name): dropped
        if text.startswith('---\n'):
            end = text.find('\n---', 4)
            if end >= 0:
                text = text[end + 4:]
        text = '\n'.join(l for l in text.split('\n') if 'derivcheck:' not in l)
        # a heading per document: conditions of one never carry into the next
        parts.append('# Part %d: %s\n\n%s\n' % (k + 1, os.path.basename(d), text))
out = '\n'.join(parts)
open(sys.argv[1], 'w').write(out)
print('%d lines, %d characters, %.1f pages' % (out.count('\n'), len(out), len(out) / 3000.0))
