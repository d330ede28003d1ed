#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Breaks a bench_mcu run down by code: reads the block runs that `bench_mcu run --profile-addresses
FILE` writes (configuration, block start, bytes, runs, the block's static cycles over all its runs)
and the Cortex-M4 program they ran (a build with -g, docs/MCU_BENCH.md), decodes every block with
arm-none-eabi-objdump and maps it to source with arm-none-eabi-addr2line -i, then prints per output
pixel: instructions, loads, stores and static cycles, by innermost source line, innermost inlined
function and file, and the hottest blocks with their inline chains.

The static cycles leave out the model's dynamic parts (taken conditional branches, division cycles
beyond 2): the bench's `cycles` minus the total printed here. A block's static cycles are shared
among its instructions evenly for the per-line and per-function tables (instruction, load and store
counts are exact). With --check-json the total instructions must equal the bench's JSON line of the
same configuration (exit 1 otherwise).

Usage: profile_blocks.py ELF PROFILE [--config TEXT] [--top N] [--check-json FILE]
Exit: 0, 1 (a check failed), 2 (bad arguments, unreadable or malformed input, a tool missing).
"""
import argparse
import bisect
import collections
import json
import re
import subprocess
import sys


def fail(message):
    print('profile_blocks: ' + message, file=sys.stderr)
    sys.exit(2)


def run_tool(args):
    try:
        return subprocess.run(args, capture_output=True, text=True, check=True).stdout
    except FileNotFoundError:
        fail(args[0] + ' not found (tools/install-deps.sh mcu)')
    except subprocess.CalledProcessError as e:
        fail('%s failed: %s' % (args[0], e.stderr.strip()))


def read_blocks(path, config):
    """The rows of one configuration: (start, bytes, runs, cycles), and its name."""
    rows, names = [], []
    try:
        lines = open(path, encoding='utf-8').read().splitlines()
    except OSError as e:
        fail('%s: %s' % (path, e.strerror))
    for number, line in enumerate(lines, 1):
        fields = line.split('\t')
        if len(fields) != 5:
            fail('%s:%d: expected 5 tab-separated fields (configuration, start, bytes, runs, cycles)' % (path, number))
        if config not in fields[0]:
            continue
        if fields[0] not in names:
            names.append(fields[0])
        try:
            rows.append((int(fields[1], 16), int(fields[2]), int(fields[3]), int(fields[4])))
        except ValueError:
            fail('%s:%d: expected a hexadecimal start and decimal bytes, runs and cycles' % (path, number))
    if len(names) != 1:
        fail('%s: %s configuration matches %r (--config selects one): %s' %
             (path, 'no' if not names else 'more than one', config, '; '.join(names)))
    return rows, names[0]


def disassembly(elf):
    code = {}
    for line in run_tool(['arm-none-eabi-objdump', '-d', '--no-show-raw-insn', elf]).splitlines():
        m = re.match(r'\s+([0-9a-f]+):\s+(\S+)\s*(.*)', line)
        if m:
            code[int(m.group(1), 16)] = (m.group(2), m.group(3))
    return code


def short_name(name):
    """The function's own name: no namespaces, template arguments, parameters or return type."""
    name = name.replace('(anonymous namespace)::', '')
    while True:
        shorter = re.sub(r'<[^<>]*>', '', name)
        if shorter == name:
            break
        name = shorter
    name = re.sub(r'\{lambda\(.*?\)#\d+\}', 'lambda', name)
    name = re.sub(r'\(.*', '', name).split(' ')[-1]
    return name.split('::')[-1] or '?'


def inline_chains(elf, addresses):
    """address -> [(function, file:line), ...] innermost first."""
    chains, current, lines, i = {}, None, [], 0
    for chunk in range(0, len(addresses), 2000):
        part = [hex(a) for a in addresses[chunk:chunk + 2000]]
        lines += run_tool(['arm-none-eabi-addr2line', '-a', '-f', '-i', '-C', '-e', elf] + part).splitlines()
    while i < len(lines):
        if re.match(r'0x[0-9a-f]+$', lines[i]):
            current = int(lines[i], 16)
            chains[current] = []
            i += 1
            continue
        function = short_name(lines[i])
        place = re.sub(r'.*/', '', lines[i + 1] if i + 1 < len(lines) else '').split(' ')[0]
        chains[current].append((function, place))
        i += 2
    return chains


def kind(mnemonic):
    m = mnemonic.split('.')[0]
    if m.startswith(('ldm', 'pop')):
        return 'ldm'
    if m.startswith(('stm', 'push')):
        return 'stm'
    if m.startswith('ldr'):
        return 'ld'
    if m.startswith('str'):
        return 'st'
    return 'other'


def tally(rows, code, chains):
    """Counters per group (line, function, file) and per block."""
    addresses = sorted(code)
    groups = {'line': collections.defaultdict(collections.Counter),
              'function': collections.defaultdict(collections.Counter),
              'file': collections.defaultdict(collections.Counter)}
    blocks, total = [], collections.Counter()
    for start, size, runs, cycles in rows:
        i = bisect.bisect_left(addresses, start)
        body = []
        while i < len(addresses) and addresses[i] < start + size:
            body.append(addresses[i])
            i += 1
        if not body:
            fail('no instruction decoded in the block at 0x%x: not this program\'s profile?' % start)
        block = collections.Counter(cyc=cycles, ins=runs * len(body))
        for a in body:
            function, place = (chains.get(a) or [('?', '?')])[0]
            one = collections.Counter(cyc=cycles / len(body), ins=runs)
            one[kind(code[a][0])] += runs
            block[kind(code[a][0])] += runs
            for name, key in (('line', place), ('function', function), ('file', place.split(':')[0])):
                groups[name][key].update(one)
        total.update(block)
        blocks.append((start, size, runs, block))
    return groups, blocks, total


def row(label, c, pixels):
    return '%-44s %8.2f %7.2f %6.2f %6.2f %6.2f' % (label[:44], c['cyc'] / pixels, c['ins'] / pixels,
                                                    c['ld'] / pixels, c['st'] / pixels,
                                                    (c['ldm'] + c['stm']) / pixels)


def report(name, pixels, groups, blocks, total, chains, top):
    header = '%-44s %8s %7s %6s %6s %6s' % ('', 'cyc/px', 'ins/px', 'ld', 'st', 'ldm/stm')
    print('%s: %d pixels; static cycles (without taken-branch and division extras)' % (name, pixels))
    print(header)
    print(row('total', total, pixels))
    for title in ('line', 'function', 'file'):
        print('\nby innermost ' + title)
        print(header)
        for key, c in sorted(groups[title].items(), key=lambda kv: -kv[1]['cyc'])[:top]:
            print(row(key, c, pixels))
    print('\nhottest blocks (start, bytes, runs, cycles a run, inline chain)')
    for start, size, runs, c in sorted(blocks, key=lambda b: -b[3]['cyc'])[:top]:
        chain = ' < '.join('%s@%s' % x for x in chains.get(start, [])[:4])
        print('%08x %4dB %9d %6.1f  %6.2f cyc/px  %s' % (start, size, runs, c['cyc'] / runs, c['cyc'] / pixels, chain))


def check(json_path, name, total):
    try:
        lines = [json.loads(l) for l in open(json_path, encoding='utf-8') if l.startswith('{')]
    except (OSError, ValueError) as e:
        fail('%s: %s' % (json_path, e))
    words = name.split()
    for j in lines:
        if [j.get('mesh'), j.get('output'), j.get('tiling'), j.get('method'), j.get('opt')] == words[:5]:
            if j['instructions'] != total['ins']:
                print('profile_blocks: %d instructions from the blocks, %d in %s' %
                      (total['ins'], j['instructions'], json_path))
                sys.exit(1)
            print('instructions equal to the bench\'s: %d' % total['ins'])
            return
    fail('%s: no JSON line of configuration %r' % (json_path, name))


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    p.add_argument('elf')
    p.add_argument('profile')
    p.add_argument('--config', default='', help='text in the configuration column that selects one configuration')
    p.add_argument('--top', type=int, default=25)
    p.add_argument('--check-json', help='bench_mcu run output: the instructions must equal its line\'s')
    a = p.parse_args()
    rows, name = read_blocks(a.profile, a.config)
    m = re.search(r'\b(\d+)x(\d+)\b', name)
    if not m:
        fail('%s: no output size (WxH) in configuration %r' % (a.profile, name))
    pixels = int(m.group(1)) * int(m.group(2))
    code = disassembly(a.elf)
    wanted = sorted({x for start, size, _, _ in rows for x in code if start <= x < start + size})
    chains = inline_chains(a.elf, wanted)
    groups, blocks, total = tally(rows, code, chains)
    report(name, pixels, groups, blocks, total, chains, a.top)
    if a.check_json:
        check(a.check_json, name, total)


if __name__ == '__main__':
    main()
