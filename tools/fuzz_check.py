#!/usr/bin/env python3
"""Scene mutations through `ryushi check`, as a user's mistakes would reach it.

    python3 tools/fuzz_check.py BUILD/ryushi [--count 300] [--seed 1] [--timeout 60] [--keep DIR]
                                             [--no-ulimit]

Takes the shipped scenes (scenes/*.toml), applies one or two random mutations to each chosen
scene (a number made extreme or not a number, a string or array changed, a line deleted,
repeated or swapped, a key of `ryushi keys` added with a value of the wrong kind, a section
header dropped, the text cut short, a [health] table with random values, a --set override) and
runs `ryushi check` on it under `ulimit -v` of 4 GiB (the memory guard reads it, so a
mutation to a tiny spacing is refused rather than allocated; --no-ulimit for an AddressSanitizer
build, whose shadow memory needs the address space). Each must exit 0, or 2 with one
line `ryushi: ` naming the place (the file's `path:line:col`, the file, or `--set`); a crash,
another exit code, or a check that runs past --timeout seconds (a hang) is a finding. The
mutations are seeded: a finding is reproduced with the same --seed and written to --keep.

Exit 0 when every mutation passed, 1 with findings (listed), 2 on bad arguments.
"""
import argparse
import os
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(os.path.dirname(HERE), "scenes")

NUMBERS = ["0", "-0.0", "-1", "1e-300", "1e300", "1e9", "-1e9", "nan", "inf", "-inf", "3", "0.5", "1e-7",
           "123456789012", "2", "0.001", "-0.5", "1.0e-3", "7"]
STRINGS = ["\"wcsph\"", "\"mps\"", "\"isph\"", "\"swe\"", "\"box\"", "\"sphere\"", "\"cylinder\"", "\"mesh\"",
           "\"warn\"", "\"stop\"", "\"\"", "\"no_such\"", "\"../../etc/passwd\"", "\"leapfrog\"", "\"midpoint\"",
           "\"multigrid\"", "\"x * y + sin(t)\"", "\"1/0\"", "\"beyond_resolved_flow\""]
ARRAYS = ["[]", "[0.0]", "[0.0, 0.0, 0.0, 0.0]", "[nan, 0.0]", "[1e300, -1e300]", "[\"a\", \"b\"]", "[0.1, 0.2]",
          "[0.1, 0.2, 0.3]", "[[0.0]]"]


def keys_of(binary):
    out = subprocess.run([binary, "keys"], capture_output=True, text=True, check=True).stdout
    return [m.group(1) for m in re.finditer(r"^  ([a-z_]+\.[a-z_0-9.]+)  ", out, re.M)]


def random_value(rng):
    kind = rng.randrange(4)
    return [rng.choice(NUMBERS), rng.choice(STRINGS), rng.choice(ARRAYS), rng.choice(["true", "false"])][kind]


def mutate(text, rng, keys):
    lines = text.split("\n")
    # Mostly values (a mistyped number or name reaches the checks behind the parser); structure
    # less often (most of those stop at the parser).
    op = rng.choices(range(11), weights=[5, 2, 2, 1, 1, 1, 3, 0.5, 0.5, 1, 1])[0]

    def add_to_section(section, line):
        head = f"[{section}]"
        if head in lines:
            k = lines.index(head)
            return "\n".join(lines[:k + 1] + [line] + lines[k + 1:])
        return text + f"\n{head}\n{line}\n"
    if op == 0:  # a number
        spots = list(re.finditer(r"(?<![\w.])-?\d+(\.\d*)?(e-?\d+)?(?![\w.])", text))
        if spots:
            m = rng.choice(spots)
            return text[:m.start()] + rng.choice(NUMBERS) + text[m.end():]
    if op == 1:  # a string
        spots = list(re.finditer(r"\"[^\"\n]*\"", text))
        if spots:
            m = rng.choice(spots)
            return text[:m.start()] + rng.choice(STRINGS) + text[m.end():]
    if op == 2:  # an array
        spots = list(re.finditer(r"\[[^\[\]\n]*\]", text))
        spots = [m for m in spots if "=" in text[text.rfind("\n", 0, m.start()) + 1:m.start()]]
        if spots:
            m = rng.choice(spots)
            return text[:m.start()] + rng.choice(ARRAYS) + text[m.end():]
    if op == 3 and lines:  # delete a line
        del lines[rng.randrange(len(lines))]
        return "\n".join(lines)
    if op == 4 and lines:  # repeat a line
        k = rng.randrange(len(lines))
        lines.insert(k, lines[k])
        return "\n".join(lines)
    if op == 5 and len(lines) > 1:  # swap two lines
        a, b = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[a], lines[b] = lines[b], lines[a]
        return "\n".join(lines)
    if op == 6 and keys:  # a key of the schema with a value of any kind, in its own section
        key = rng.choice(keys)
        section, name = key.split(".", 1)
        if "." not in name:
            return add_to_section(section, f"{name} = {random_value(rng)}")
    if op == 7:  # drop a section header
        heads = [k for k, l in enumerate(lines) if l.startswith("[")]
        if heads:
            del lines[rng.choice(heads)]
            return "\n".join(lines)
    if op == 8 and text:  # cut short
        return text[:rng.randrange(len(text))]
    if op == 9:  # a [health] table
        if "[health]" not in text:
            parts = ["[health]"]
            for name in ("action", "density_deviation", "energy_rise", "pressure_factor", "wall_penetration"):
                if rng.random() < 0.6:
                    parts.append(f"{name} = {random_value(rng)}")
            return text + "\n" + "\n".join(parts) + "\n"
    if op == 10:  # an unknown key, or a known key in the wrong section
        return add_to_section(rng.choice(['time', 'method', 'particles', 'output', 'nonsense']),
                              f"{rng.choice(['cfl', 'nope', 'spacing', 'layers', 'action'])} = {random_value(rng)}")
    return text + "\n# unchanged\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary")
    ap.add_argument("--count", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--keep", default=None, help="write the findings' inputs here")
    ap.add_argument("--no-ulimit", action="store_true", help="no address-space limit (AddressSanitizer)")
    a = ap.parse_args()
    if not os.access(a.binary, os.X_OK):
        print(f"fuzz_check: {a.binary} is not an executable", file=sys.stderr)
        sys.exit(2)
    rng = random.Random(a.seed)
    keys = keys_of(a.binary)
    scenes = sorted(f for f in os.listdir(SCENES) if f.endswith(".toml"))
    work = tempfile.mkdtemp(prefix="ryushi_fuzz_check_")
    # Relative paths of the scenes (meshes, rasters) resolve beside the mutated file.
    for entry in os.listdir(SCENES):
        if os.path.isdir(os.path.join(SCENES, entry)):
            os.symlink(os.path.join(SCENES, entry), os.path.join(work, entry))

    def limit_memory():
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))

    outcomes = {"accepted": 0, "refused": 0}
    findings = []
    for n in range(a.count):
        scene = rng.choice(scenes)
        text = open(os.path.join(SCENES, scene)).read()
        for _ in range(rng.randint(1, 2)):
            text = mutate(text, rng, keys)
        path = os.path.join(work, f"m{n:03d}_{scene}")
        with open(path, "w") as f:
            f.write(text)
        cmd = [a.binary, "check", path]
        if rng.random() < 0.15 and keys:
            cmd += ["--set", f"{rng.choice(keys)}={random_value(rng)}"]
        try:
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout,
                               preexec_fn=None if a.no_ulimit else limit_memory)
        except subprocess.TimeoutExpired:
            findings.append((path, cmd, f"no answer in {a.timeout:g} s (a hang)"))
            continue
        message = r.stderr.strip()
        if r.returncode == 0:
            outcomes["accepted"] += 1
        elif r.returncode == 2 and message.count("\n") == 0 and (
                message.startswith(f"ryushi: {path}") or message.startswith("ryushi: --set ")):
            outcomes["refused"] += 1
        else:
            findings.append((path, cmd, f"exit {r.returncode}: {message[-400:]}"))
    print(f"fuzz_check: {a.count} mutations of {len(scenes)} scenes (seed {a.seed}): "
          f"{outcomes['accepted']} accepted, {outcomes['refused']} refused with a place, {len(findings)} findings")
    for path, cmd, what in findings:
        print(f"  {' '.join(cmd)}\n    {what}")
        if a.keep:
            os.makedirs(a.keep, exist_ok=True)
            shutil.copy(path, a.keep)
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(1 if findings else 0)


if __name__ == "__main__":
    main()
