"""Shared look of the figures: Agg backend, fonts, PNG+PDF output, titles, CLI error handling."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from _data import InputError  # noqa: E402

plt.rcParams.update({
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "legend.fontsize": 8,
    "figure.dpi": 150,
    "savefig.dpi": 150,
    "savefig.bbox": "tight",
    "pdf.fonttype": 42,
})

# Theory wave-speed lines, the same in every figure.
THEORY_STYLE = {
    "c_l": dict(color="tab:blue", ls="-", label="$c_l$"),
    "c_s": dict(color="tab:green", ls="--", label="$c_s$"),
    "sqrt2_c_s": dict(color="tab:purple", ls=":", label=r"$\sqrt{2}\,c_s$"),
}


def save(fig, prefix, description=None):
    """Write PREFIX.png and PREFIX.pdf, creating the folder. `description` (text, e.g. the legend's
    counts as JSON) goes into the PNG's Description chunk, where the study report reads it."""
    folder = os.path.dirname(os.path.abspath(prefix))
    os.makedirs(folder, exist_ok=True)
    fig.savefig(f"{prefix}.png", metadata={"Description": description} if description else None)
    fig.savefig(f"{prefix}.pdf")
    plt.close(fig)


def sci(value):
    """1e-05 -> '$10^{-5}$', 5e-06 -> '$5\\times10^{-6}$', 0.2 -> '0.2' (mathtext)."""
    if value is None or not math.isfinite(value):
        return "?"
    if value != 0 and (abs(value) < 1e-3 or abs(value) >= 1e4):
        exponent = math.floor(math.log10(abs(value)))
        mantissa = value / 10 ** exponent
        if abs(mantissa - round(mantissa)) < 1e-9:
            mantissa = int(round(mantissa))
        if mantissa == 1:
            return f"$10^{{{exponent}}}$"
        return f"${mantissa:g}\\times10^{{{exponent}}}$"
    return f"{value:g}"


def run_parts(run):
    """{key: text} of a run's parameters from its root attributes, in title order."""
    a = run.attrs
    parts = {}
    if "nu" in a:
        parts["nu"] = f"$\\nu$ = {float(a['nu']):g}"
    if "f" in a:
        parts["f"] = f"$f$ = {float(a['f']):g}"
    if "V0" in a and "c_s" in a:
        parts["V0"] = f"$V_0/c_s$ = {sci(float(a['V0']) / float(a['c_s']))}"
    if "lambda" in a and "H" in a:
        parts["lambda"] = f"$\\lambda/H$ = {float(a['lambda']) / float(a['H']):g}"
    if "H" in a and "h" in a:
        integration = run.config.get("mesh", {}).get("integration")
        parts["mesh"] = (f"mesh $H$/{round(float(a['H']) / float(a['h']))}"
                         + (f" ({integration})" if integration else ""))
    if "rho" in a and float(a["rho"]) != 1000.0:
        parts["rho"] = f"$\\rho$ = {float(a['rho']):g} kg/m$^3$"
    if str(a.get("complete", "1")) in ("0", "False"):
        parts["complete"] = f"INCOMPLETE ({a.get('end_reason', '?')})"
    return parts


def run_label(run):
    """'nu = 0.2, f = 1.5, V0/c_s = 1e-5, lambda/H = 2, mesh H/32 (reduced)' from root attributes."""
    return ", ".join(run_parts(run).values())


COLUMN_LABELS = {
    "nu": "$\\nu$", "f": "$f$", "V0_over_cs": "$V_0/c_s$", "lambda_over_H": "$\\lambda/H$",
    "elements_per_H": "$H/h$", "rho": "$\\rho$", "integration": "integration",
    "dt_times_cs": "$\\Delta t\\, c_s$",
}


def common_label(rows, columns=tuple(COLUMN_LABELS), skip=()):
    """The parameters that have one value over all rows, as a title line."""
    parts = []
    for column in columns:
        if column in skip or column not in rows[0]:
            continue
        values = {str(r[column]) for r in rows}
        if len(values) == 1:
            value = rows[0][column]
            text = sci(value) if isinstance(value, float) else str(value)
            text += " kg/m$^3$" if column == "rho" else ""
            parts.append(f"{COLUMN_LABELS[column]} = {text}")
    return ", ".join(parts)


def cli(main):
    """Run main(); a bad input becomes 'script: error: ...' on stderr and exit status 2."""
    try:
        sys.exit(main())
    except InputError as err:
        print(f"{os.path.basename(sys.argv[0])}: error: {err}", file=sys.stderr)
        sys.exit(2)
