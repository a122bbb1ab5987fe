"""CLI of the dynamic engine: ``bearingsim simulate CASE.toml --out run.nc [--resume]``.

The lead wires it with ``cli_dynamics.register(app)``.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer


def register(app: typer.Typer) -> None:
    """Add the ``simulate`` command to the bearingsim typer app."""

    @app.command()
    def simulate(case: Path = typer.Argument(..., help="case TOML file (see examples/spindle-7011.toml)"),
                 out: Path = typer.Option(..., "--out", "-o", help="output netCDF file (streamed in chunks)"),
                 resume: bool = typer.Option(False, "--resume", help="continue from the checkpoint OUT.ckpt.npz"),
                 duration: Optional[str] = typer.Option(None, "--duration", help="override the case duration, e.g. '2 ms'"),
                 json_out: bool = typer.Option(False, "--json", help="print a JSON summary (SI)"),
                 quiet: bool = typer.Option(False, "--quiet", help="no progress bar")):
        """Run a dynamic simulation of rings, balls and cage in time (issue 5)."""
        import dataclasses

        from rich.console import Console

        from .dynamics.case import load_case
        from .dynamics.run import simulate as run_sim
        from .units import parse_quantity

        c = load_case(case)
        if duration is not None:
            c = dataclasses.replace(c, duration=parse_quantity(duration, "time", "--duration"))
        con = Console(stderr=True)
        res = run_sim(c, out=out, resume=resume, progress=not (quiet or json_out), console=con)
        summary = dict(res.summary)
        summary["output"] = str(out)
        try:
            summary["steady_state"] = res.steady_state()
        except Exception:  # noqa: BLE001 - a summary must not hide the saved output
            pass
        if json_out:
            typer.echo(json.dumps(summary))
        else:
            con.print(f"wrote {out}: {summary['simulated_seconds'] * 1e3:.4g} ms simulated in "
                      f"{summary['wall_seconds']:.3g} s ({summary['wall_per_simulated_second']:.4g} wall s per "
                      f"simulated s, {summary['steps']} steps)")
            ss = summary.get("steady_state")
            if ss:
                con.print(f"last half of the run: heat {ss['heat_generation_total_W']:.4g} W (ball-inner "
                          f"{ss['power_loss_inner']:.4g}, ball-outer {ss['power_loss_outer']:.4g}, ball-cage "
                          f"{ss['power_loss_cage']:.4g}, land {ss['power_loss_land']:.4g}; rolling resistance "
                          f"{ss['power_loss_rolling']:.4g} of the raceway terms); inner-ring friction torque "
                          f"{ss['inner_ring_friction_torque']:.4g} N·m; cage {ss['cage_angular_speed']:.5g} rad/s")
