#!/usr/bin/env python3
"""The Markdown table of run.py's results.json (one row per case), for RESULTS.md.
Usage: table.py OUT_DIR/results.json"""
import json
import sys

rows = json.load(open(sys.argv[1]))
print("| case | N | least_squares | VF given | VF at the optimum | VF after | VF ref. ball given -> after | "
      "z given -> after (tol 1e-6) | rattlers given -> after | radius change mean / max | centre move mean (radii) | "
      "share kept | stage s (triangulation, solve) | valid |")
print("|" + "---|" * 14)
for r in rows.values():
    print(f"| {r['case']} | {r['particles']} | `{r['least_squares']}` | {r['vf_before']:.4f} | {r['vf_optimum']:.4f} | "
          f"{r['vf_after']:.4f} | {r['vf_ref_before']:.4f} -> {r['vf_ref_after']:.4f} | {r['z_before']:.2f} -> {r['z_after']:.2f} | "
          f"{100 * r['rattlers_before']:.1f} % -> {100 * r['rattlers_after']:.1f} % | {r['radius_change_mean']:.3f} / "
          f"{r['radius_change_max']:.3f} | {r['move_mean']:.3f} | {r['kept_share']:g} | {r['stage_seconds']:.2f} "
          f"({r['triangulation_seconds']:.2f}, {r['solve_seconds']:.2f}) | {'yes' if r['exit'] == 0 else 'exit ' + str(r['exit'])} |")
