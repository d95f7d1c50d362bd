#!/usr/bin/env python3
"""Test cargo-mutants' mutants one at a time, the cheapest test binary first.

cargo-mutants runs the test binaries in name order, so with the G75.1
harness binaries every mutant waits about 110 s for `g75_exact` before
`survivors` (under a second) runs. This script tests the same mutants with
the same binaries, in the order given, building each just before it
runs, and stops at the first binary that fails, as `cargo test` does.
The verdicts are cargo-mutants' own:

- UNVIABLE: the mutated tree does not build (a mutation inside a
  function body builds for every binary or for none, so the first
  binary's build decides it);
- CAUGHT: a binary fails (the failing tests are listed);
- TIMEOUT: a binary runs past its limit (60 s for the binaries that take
  under a second, the given limit for the others); a hang, or a slow test;
- MISSED: every binary passes.

Usage, from a clean worktree of its own (it mutates the tree in place and
restores it with `git checkout .` before each mutant):

    cargo mutants --list --json --diff -f FILE > mutants.json
    BINS="survivors g75_mutants g75_harnesses unwind g75_exact" \\
        python3 proofs/scripts/mutants_cheapest_first.py \\
        WORKTREE mutants.json NAMES OUT [LIMIT_SECONDS]

A name `lib:PACKAGE` in BINS stands for that package's own unit tests
(`cargo test -p PACKAGE --lib`), for instance `lib:cycleref` for the
kernels' tests beside `engine/real.rs`.

NAMES is a file of mutant names (one a line, as cargo-mutants prints
them); OUT gets one tab-separated line a mutant, appended as it is
decided. Builds and tests run under `nice -n 19` with one build job.
"""
import json
import os
import subprocess
import sys
import time

wt, mutants_json, names_file, out = sys.argv[1:5]
limit = int(sys.argv[5]) if len(sys.argv) > 5 else 900
mutants = {m['name']: m for m in json.load(open(mutants_json))}
names = [line.strip() for line in open(names_file) if line.strip()]
BINS = os.environ.get('BINS', 'survivors g75_mutants g75_harnesses unwind g75_exact').split()
ENV = 'CARGO_BUILD_JOBS=1 nice -n 19 '
# A hang in a binary that takes under a second is known long before the
# others' limit.
FAST = {'survivors': 60, 'boundaries': 60, 'g75_golden': 60, 'kani_covers': 60, 'no_alloc': 60,
        'contracts': 60, 'lib:cycleref': 60}


def run(cmd, seconds=None):
    """(exit status, output) of `cmd` in the worktree; status None past `seconds`."""
    try:
        r = subprocess.run(ENV + cmd, shell=True, cwd=wt, capture_output=True, text=True, timeout=seconds)
        return r.returncode, r.stdout + r.stderr
    except subprocess.TimeoutExpired:
        subprocess.run(['pkill', '-f', f'{wt}/target/debug/deps/'])
        return None, ''


with open(out, 'a') as log:
    for name in names:
        start = time.time()
        subprocess.run(['git', 'checkout', '-q', '.'], cwd=wt)
        # A failing proptest leaves its seed in a regressions file, which
        # would be replayed against every later mutant: not the tree's test.
        subprocess.run(['git', 'clean', '-fq', '--', '*.proptest-regressions'], cwd=wt)
        m = mutants[name]
        patch = subprocess.run(['patch', '-s', '-p0', m['file']], input=m['diff'], text=True, cwd=wt,
                               capture_output=True)
        if patch.returncode:
            log.write(f"PATCHFAIL\t{name}\n")
            log.flush()
            continue
        verdict, by = 'MISSED', ''
        for b in BINS:
            # Each binary is built just before it runs: a mutant caught by
            # the first binary never waits for the others to build.
            # `lib:PACKAGE` is that package's own unit tests.
            target = f'-p {b[4:]} --lib' if b.startswith('lib:') else f'-p cycleref-proofs --test {b}'
            status, _ = run(f'cargo test {target} --no-run', 1800)
            if status != 0:
                verdict, by = 'UNVIABLE', b
                break
            status, output = run(f'cargo test -q {target}', FAST.get(b, limit))
            if status is None:
                verdict, by = 'TIMEOUT', b
                break
            if status != 0:
                failed = sorted({line.strip() for line in output.split('\n')
                                 if line.startswith('    ') and ' ' not in line.strip()})
                verdict, by = 'CAUGHT', b + ':' + ','.join(failed[:4])
                break
        log.write(f"{verdict}\t{name}\t{by}\t{int(time.time() - start)}s\n")
        log.flush()
subprocess.run(['git', 'checkout', '-q', '.'], cwd=wt)
