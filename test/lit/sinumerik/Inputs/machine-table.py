#!/usr/bin/env python3
"""Checks the machine-specific construct table of frontend/sinumerik/MachineOnly.cpp against the
operator table: every name in it must be an operator of sinumerik-operators.tsv.

usage: machine-table.py MachineOnly.cpp sinumerik-operators.tsv"""
import re
import sys

src, tsv = sys.argv[1:3]
names = re.findall(r'\{"([A-Z0-9_]+)", k[A-Z][A-Za-z]+\}', open(src).read())
known = {line.split('\t')[0].upper() for line in open(tsv, encoding='utf-8') if line.strip()}
for n in names:
    if n not in known:
        print("NOT IN THE OPERATOR TABLE:", n)
print(f"{len(names)} constructs")
