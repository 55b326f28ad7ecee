#!/usr/bin/env python3
"""Turn a Google Benchmark JSON file into the book's HTML table (median of the repetitions,
ratios against the hand-written loop of the same run)."""
import json
import sys

data = json.load(open(sys.argv[1]))
med = {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") == "median":
        med[b["run_name"].replace("BM_", "")] = b["ns_per_step"]
hand = med.get("hand_loop")
ctx = data.get("context", {})
print("<table class=\"vibook-bench\">")
print("<tr><th>Störmer–Verlet on Kepler</th><th>ns per step (median)</th><th>ratio to hand loop</th></tr>")
for name in ("hand_loop", "vibook", "odeint"):
    if name in med:
        ratio = med[name] / hand if hand else float("nan")
        print(f"<tr><td>{name}</td><td>{med[name]:.2f}</td><td>{ratio:.3f}</td></tr>")
print("</table>")
if hand and "vibook" in med and "odeint" in med:
    r_hand = med["vibook"] / hand
    r_odeint = med["vibook"] / med["odeint"]
    def verdict(ok):
        return "<b>met</b>" if ok else "<b>not met</b>"
    print("<p>Targets, evaluated on this run: vibook within 1.1&times; the hand loop &mdash; "
          f"{verdict(r_hand <= 1.1)} (ratio {r_hand:.3f}); vibook faster than Odeint &mdash; "
          f"{verdict(r_odeint < 1.0)} (vibook/Odeint {r_odeint:.3f}).</p>")
print(f"<p>Measured on {ctx.get('num_cpus', '?')} CPU(s) at {ctx.get('mhz_per_cpu', '?')} MHz, "
      f"{ctx.get('date', '')}, build type {ctx.get('library_build_type', '?')} of the benchmark "
      "library; median of 5 repetitions.</p>")
