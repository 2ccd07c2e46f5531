"""Charts of a TiledRayCast benchmark CSV, drawn with VTK's own chart classes.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/plot_benchmarks.py \
        results.csv --output-dir plots [--title-suffix "GPU: NVIDIA H100"] \
        [--default-setting "compute default,fragment default"]

With the tiledraycast module importable no X display is needed (its EGL window is used);
without it VTK's X window needs one: ``xvfb-run -a /usr/bin/python3 Benchmarks/...``.
The CSV has one row per scene, mapper, setting and image size; empty cells or ``nan`` mean not
measured. Written to the output directory:

    pareto_<scene>_<size>.png  median frame time against RMSE, per mapper, with the Pareto front
    scaling_<size>.png         median frame time against tets: ours at the default setting,
                               the other mappers at their lowest-RMSE setting of each scene
    pareto_front.md            Pareto-front rows per scene and size, and VTK/ours ratios
"""
import argparse
import csv
import math
import os
import re
import sys

try:  # registers the EGL window factory: charts render without an X display
    import tiledraycast  # noqa: F401
    HEADLESS = True
except ImportError:
    HEADLESS = False

from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartLegend, vtkChartXY, vtkPlotPoints
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingContext2D import vtkPen
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

# mapper -> (legend name, RGB colour, marker), in legend order.
FAMILIES = {
    "ours": ("TiledRayCast (ours)", (214, 39, 40), vtkPlotPoints.CIRCLE),
    "projected_tetrahedra": ("Projected tetrahedra (VTK)", (31, 119, 180), vtkPlotPoints.SQUARE),
    "bunyk_raycast": ("Bunyk ray cast (VTK)", (44, 160, 44), vtkPlotPoints.DIAMOND),
    "zsweep": ("ZSweep (VTK)", (148, 103, 189), vtkPlotPoints.CROSS),
    "resample_gpu": ("Resample + GPU ray cast (VTK)", (255, 127, 14), vtkPlotPoints.PLUS),
}
NUMERIC = ("tets", "median_ms", "rmse")
RMSE_FLOOR = 0.01


def read_rows(path):
    """Rows of the CSV as dicts (NUMERIC columns as floats), skipping rows with no frame time."""
    with open(path, newline="") as stream:
        reader = csv.DictReader(stream)
        missing = {"scene", "image_size", "mapper", "setting"}.union(NUMERIC).difference(
            reader.fieldnames or ())
        if missing:
            raise SystemExit("%s: missing columns %s" % (path, ", ".join(sorted(missing))))
        rows = []
        for record in reader:
            for key in NUMERIC:
                record[key] = float(record[key] or "nan")  # empty: not measured
            if math.isfinite(record["median_ms"]) and record["median_ms"] > 0:
                rows.append(record)
    return rows


def size_text(size):
    """'1024' -> '1024² px'; other forms ('1024x768') are kept as they are."""
    return "%s² px" % size if re.fullmatch(r"[0-9]+", size) else "%s px" % size


def safe(text):
    """text with runs of characters other than letters, digits, '.', '-' as '_' (file names)."""
    return re.sub(r"[^A-Za-z0-9.-]+", "_", text)


def family(mapper):
    """Legend name, colour and marker of a mapper (unknown mappers are grey circles)."""
    return FAMILIES.get(mapper, (mapper, (110, 110, 110), vtkPlotPoints.CIRCLE))


def pareto_front(rows):
    """Rows not dominated in both median time and RMSE, fastest first (rows with RMSE only)."""
    front, best = [], math.inf
    for row in sorted((r for r in rows if math.isfinite(r["rmse"])),
                      key=lambda r: (r["median_ms"], r["rmse"])):
        if row["rmse"] < best:
            front.append(row)
            best = row["rmse"]
    return front


def log_range(values):
    """An axis range around positive values, padded by a fifth of a decade each side."""
    return min(values) / 10 ** 0.2, max(values) * 10 ** 0.2


def tick_label(value):
    """Short label of a tick value: 0.05, 20, 5000, 200k, 2M."""
    if value >= 1e6:
        return "%gM" % (value / 1e6)
    return "%gk" % (value / 1e3) if value >= 1e4 else "%g" % value


def set_log_ticks(axis, low, high):
    """Ticks at 1-2-5, 1-3 or 1 x 10^k in [low, high], the first giving 3 to 13 ticks.

    VTK 9.1 takes custom tick positions of an active log axis in log10 units, and its own log
    ticks switch to '1e+06'-style labels above 10^5, so the ticks are set here.
    """
    decades = range(math.floor(math.log10(low)), math.ceil(math.log10(high)) + 1)
    for steps in ((1, 2, 5), (1, 3), (1,), range(1, 10)):
        ticks = [m * 10.0 ** k for k in decades for m in steps if low <= m * 10.0 ** k <= high]
        if 3 <= len(ticks) <= 13:
            break
    positions, labels = vtkDoubleArray(), vtkStringArray()
    for tick in ticks:
        positions.InsertNextValue(math.log10(tick))
        labels.InsertNextValue(tick_label(tick))
    axis.SetCustomTickPositions(positions, labels)


def add_series(chart, xs, ys, name, colour, marker, line=False):
    """Add a point plot (or a line plot with markers) of xs, ys to chart."""
    table = vtkTable()
    for label, values in (("x", xs), (name, ys)):
        array = vtkDoubleArray()
        array.SetName(label)
        for value in values:
            array.InsertNextValue(value)
        table.AddColumn(array)
    plot = chart.AddPlot(vtkChart.LINE if line else vtkChart.POINTS)
    plot.SetInputData(table, 0, 1)
    plot.SetLabel(name)
    plot.SetColor(colour[0], colour[1], colour[2], 255)
    plot.SetMarkerStyle(marker)
    plot.SetMarkerSize(9 if marker != vtkPlotPoints.NONE else 0)
    plot.SetWidth(2.0)
    return plot


def make_chart(title, x_title, y_title, x_values, y_values):
    """A chart with log axes fitted to the values and the legend outside, right of the plot."""
    chart = vtkChartXY()
    chart.SetTitle(title)
    chart.GetTitleProperties().SetFontSize(20)
    chart.GetTitleProperties().BoldOn()
    for position, text, values in ((vtkAxis.BOTTOM, x_title, x_values),
                                   (vtkAxis.LEFT, y_title, y_values)):
        axis = chart.GetAxis(position)
        axis.SetTitle(text)
        axis.GetTitleProperties().SetFontSize(16)
        axis.GetLabelProperties().SetFontSize(14)
        axis.SetLogScale(True)
        axis.SetBehavior(vtkAxis.FIXED)
        low, high = log_range(values)
        axis.SetUnscaledRange(low, high)
        set_log_ticks(axis, low, high)
    chart.SetShowLegend(True)
    legend = chart.GetLegend()
    legend.SetInline(False)
    legend.SetHorizontalAlignment(vtkChartLegend.RIGHT)
    legend.SetVerticalAlignment(vtkChartLegend.CENTER)
    legend.GetLabelProperties().SetFontSize(14)
    return chart


def save_chart(chart, path, width=1000, height=700):
    """Render chart offscreen into a width x height PNG file."""
    view = vtkContextView()
    view.GetRenderer().SetBackground(1.0, 1.0, 1.0)
    window = view.GetRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    view.GetScene().AddItem(chart)
    window.Render()
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grabber.GetOutputPort())
    writer.Write()
    window.Finalize()


def plot_pareto(rows, scene, size, suffix, path):
    """Median time against RMSE (clamped at RMSE_FLOOR) per mapper family, with the front."""
    measured = [r for r in rows if math.isfinite(r["rmse"])]
    if not measured:
        return False
    clamp = lambda row: max(row["rmse"], RMSE_FLOOR)  # noqa: E731
    chart = make_chart("%s, %s%s" % (scene, size_text(size), suffix), "Median frame time (ms)",
                       "RMSE vs exact reference (1/255; values < %g shown at %g)"
                       % (RMSE_FLOOR, RMSE_FLOOR),
                       [r["median_ms"] for r in measured], [clamp(r) for r in measured])
    front = pareto_front(measured)  # drawn first, under the points
    add_series(chart, [r["median_ms"] for r in front], [clamp(r) for r in front], "Pareto front",
               (40, 40, 40), vtkPlotPoints.NONE, line=True).GetPen().SetLineType(vtkPen.DASH_LINE)
    mappers = [m for m in FAMILIES if any(r["mapper"] == m for r in measured)]
    mappers += sorted({r["mapper"] for r in measured}.difference(FAMILIES))
    for mapper in mappers:
        mine = [r for r in measured if r["mapper"] == mapper]
        add_series(chart, [r["median_ms"] for r in mine], [clamp(r) for r in mine],
                   *family(mapper))
    save_chart(chart, path)
    return True


def representative(rows, mapper, default_setting):
    """One row per scene for the scaling chart: ours at default_setting, others lowest RMSE."""
    chosen = {}
    for row in rows:
        if (row["mapper"] != mapper or not row["tets"] > 0
                or (mapper == "ours" and row["setting"] != default_setting)):
            continue
        key = (row["rmse"] if math.isfinite(row["rmse"]) else math.inf, row["median_ms"])
        if row["scene"] not in chosen or key < chosen[row["scene"]][0]:
            chosen[row["scene"]] = (key, row)
    return sorted((row for _, row in chosen.values()), key=lambda r: r["tets"])


def plot_scaling(rows, size, suffix, default_settings, path):
    """Median time against the number of tetrahedra, one line per mapper family (ours: one per
    setting of default_settings, a comma-separated list)."""
    series = []
    for m in list(FAMILIES) + sorted({r["mapper"] for r in rows}.difference(FAMILIES)):
        for setting in (default_settings.split(",") if m == "ours" else [None]):
            chosen = representative(rows, m, setting)
            if m == "ours" and not chosen and any(r["mapper"] == "ours" for r in rows):
                print("warning: no row of ours has setting %r at size %s; the scaling chart "
                      "leaves it out (see --default-setting)" % (setting, size), file=sys.stderr)
            series.append((m, setting, chosen))
    series = [(m, setting, chosen) for m, setting, chosen in series if chosen]
    if not series:
        return False
    points = [r for _, _, chosen in series for r in chosen]
    chart = make_chart("Frame time against mesh size, %s%s" % (size_text(size), suffix),
                       "Tetrahedra", "Median frame time (ms)",
                       [r["tets"] for r in points], [r["median_ms"] for r in points])
    markers = [vtkPlotPoints.CIRCLE, vtkPlotPoints.SQUARE, vtkPlotPoints.DIAMOND,
               vtkPlotPoints.PLUS, vtkPlotPoints.CROSS]
    for index, (mapper, setting, chosen) in enumerate(series):
        name, colour, marker = family(mapper)
        if mapper == "ours":
            name += ": " + setting
            if index > 0:  # another setting of ours: a darker shade of our colour
                colour = tuple(c // 2 for c in colour)
        # Dataset-ladder rungs (wavelet_1m, torus_3m, ...): one line per mesh family, since
        # frame time depends on the shape as much as on the size.
        groups = {}
        for r in chosen:
            match = re.match(r"^([A-Za-z]+)_\d+[km]$", r["scene"])
            groups.setdefault(match.group(1) if match else "", []).append(r)
        for i, (group, members) in enumerate(sorted(groups.items())):
            add_series(chart, [r["tets"] for r in members], [r["median_ms"] for r in members],
                       name + (" (%s)" % group if group else ""), colour,
                       markers[i % len(markers)] if group else marker,
                       line=len(members) > 1)  # one point: no line
    save_chart(chart, path)
    return True


def ratio(numerator, denominator):
    """numerator / denominator as text ('inf' over zero)."""
    return "%.3g" % (numerator / denominator) if denominator > 0 else "inf"


def describe(row):
    """'mapper `setting`, T ms, RMSE E' for a markdown line."""
    return "%s `%s`, %.3g ms, RMSE %.3g" % (row["mapper"], row["setting"], row["median_ms"],
                                            row["rmse"])


def pareto_markdown(rows, scene, size):
    """Markdown section for one scene and size: front table and ours-against-VTK ratios."""
    lines = ["## %s, %s" % (scene, size_text(size)), "",
             "| mapper | setting | median ms | RMSE (1/255) |", "|---|---|---:|---:|"]
    for row in pareto_front(rows):
        lines.append("| %s | %s | %.3f | %.4g |" % (row["mapper"], row["setting"],
                                                   row["median_ms"], row["rmse"]))
    ours = pareto_front([r for r in rows if r["mapper"] == "ours"])
    vtk = [r for r in rows if r["mapper"] != "ours" and math.isfinite(r["rmse"])]
    lines.append("")
    if not ours or not vtk:
        lines += ["No ratios: %s has no row with an RMSE." % ("ours" if not ours else "VTK"), ""]
        return lines
    fastest, finest = ours[0], ours[-1]
    vtk_finest = min(vtk, key=lambda r: (r["rmse"], r["median_ms"]))
    rivals = [r for r in vtk if r["rmse"] <= 2 * fastest["rmse"]]
    rival = min(rivals, key=lambda r: (r["median_ms"], r["rmse"])) if rivals else vtk_finest
    lines += [
        "- (a) ours fastest: %s" % describe(fastest),
        "- (b) VTK fastest with RMSE <= %.3g (2x ours fastest)%s: %s; time VTK/ours = %s" % (
            2 * fastest["rmse"], "" if rivals else " - none, so VTK's lowest RMSE",
            describe(rival), ratio(rival["median_ms"], fastest["median_ms"])),
        "- (c) lowest RMSE: %s against %s; RMSE VTK/ours = %s, time VTK/ours = %s" % (
            describe(finest), describe(vtk_finest), ratio(vtk_finest["rmse"], finest["rmse"]),
            ratio(vtk_finest["median_ms"], finest["median_ms"])), ""]
    return lines


def main():
    """Parse the arguments, read the CSV and write the charts and the markdown summary."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", help="benchmark results (one row per scene/mapper/setting/size)")
    parser.add_argument("--output-dir", required=True, help="where the PNGs and markdown go")
    parser.add_argument("--title-suffix", default="", help='e.g. "GPU: NVIDIA H100"')
    parser.add_argument("--default-setting", default="compute default,fragment default",
                        help="settings of ours shown in the scaling chart (comma-separated)")
    args = parser.parse_args()
    if not HEADLESS and not os.environ.get("DISPLAY"):
        parser.error("no X display and no tiledraycast module: put build/lib/python3/"
                     "dist-packages on PYTHONPATH, or run under xvfb-run -a")
    rows = read_rows(args.csv)
    os.makedirs(args.output_dir, exist_ok=True)
    suffix = ", " + args.title_suffix if args.title_suffix else ""
    written, markdown = [], ["# Pareto fronts: median frame time against RMSE", "",
                             "Source: `%s`%s" % (args.csv, suffix), "",
                             "Ratios: the Pareto front of ours alone against every VTK row "
                             "with an RMSE; ratios are VTK / ours.", ""]
    sizes = sorted({r["image_size"] for r in rows}, key=lambda s: (len(s), s))  # 512 < 1024
    for scene in sorted({r["scene"] for r in rows}):
        for size in sizes:
            subset = [r for r in rows if r["scene"] == scene and r["image_size"] == size]
            if not subset:
                continue
            name = "pareto_%s_%s.png" % (safe(scene), safe(size))
            if plot_pareto(subset, scene, size, suffix, os.path.join(args.output_dir, name)):
                written.append(name)
            markdown += pareto_markdown(subset, scene, size)
    for size in sizes:
        name = "scaling_%s.png" % safe(size)
        subset = [r for r in rows if r["image_size"] == size]
        if plot_scaling(subset, size, suffix, args.default_setting,
                        os.path.join(args.output_dir, name)):
            written.append(name)
    with open(os.path.join(args.output_dir, "pareto_front.md"), "w") as stream:
        stream.write("\n".join(markdown))
    for name in written + ["pareto_front.md"]:
        print(os.path.join(args.output_dir, name))


if __name__ == "__main__":
    main()
