#!/usr/bin/env python3
"""Derive the chapter's formulas with the engine during the book build.

Usage: engine_formulas.py VIBOOK GEN_DIR

For each example below, runs `vibook modified ... --format latex` and writes
GEN_DIR/modified-NAME.html: the command, the engine's description line and one display
equation per output line. Nothing in these fragments is typed by hand.
"""
import html
import subprocess
import sys

EXAMPLES = [
    ("sv-equation", "--method sv --potential generic --order 4 --cross-check"),
    ("sv-meshed", "--method sv --potential generic --order 4 --what meshed"),
    ("sv-lagrangian", "--method sv --potential generic --order 5 --what lagrangian"),
    ("se-lagrangian", "--method se-adjoint --potential generic --order 2 --what lagrangian"),
    ("se-hamiltonian", "--method se-adjoint --potential generic --order 2 --what hamiltonian"),
    ("symE-lagrangian", "--method se --potential generic --dim 2 --order 3 --what lagrangian"),
    ("vi1-lagrangian", "--method vi1 --potential generic --dim 2 --order 2 --what lagrangian"),
    ("vi1-equation", "--method vi1 --potential generic --dim 2 --order 2 --cross-check"),
    ("vi2-equation", "--method vi2 --potential generic --dim 2 --order 2 --cross-check"),
    ("vi2-lagrangian", "--method vi2 --potential generic --dim 2 --order 2 --what lagrangian"),
    ("harmonic-equation", "--method sv --potential harmonic --order 8"),
    ("kepler-lagrangian", "--method sv --potential kepler --order 2 --what lagrangian"),
]


def main() -> int:
    vibook, gen = sys.argv[1], sys.argv[2]
    for name, args in EXAMPLES:
        cmd = [vibook, "modified", *args.split(), "--format", "latex"]
        run = subprocess.run(cmd, capture_output=True, text=True, check=False)
        if run.returncode != 0:
            sys.stderr.write(f"engine_formulas: {' '.join(cmd)} failed ({run.returncode}): "
                             f"{run.stderr}\n")
            return 1
        parts = [f'<div class="engine-formula"><p><code>vibook modified {html.escape(args)} '
                 f'--format latex</code></p>']
        for line in run.stdout.splitlines():
            line = line.strip()
            if not line:
                continue
            if line.startswith("%"):
                parts.append(f"<p><em>{html.escape(line.lstrip('% '))}</em></p>")
            else:
                # derived, not a paper's equation: no number (the number's room would also
                # narrow the width at which MathJax breaks the line)
                parts.append(f"<p>\\[ {html.escape(line, quote=False)} \\notag \\]</p>")
        parts.append("</div>")
        with open(f"{gen}/modified-{name}.html", "w", encoding="utf-8") as out:
            out.write("\n".join(parts) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
