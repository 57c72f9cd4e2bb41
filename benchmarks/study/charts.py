"""Plotly charts of a bench run: speed against accuracy per regime, stability maps, sampling study."""

from __future__ import annotations

import math
from collections.abc import Sequence

import plotly.graph_objects as go
from plotly.subplots import make_subplots

from rigidrel_app.view.sampling import TOLERANCE_PX

from .methods.mpmath_slices import ROUNDING_LEVEL
from .runner import RegimeRow, ThroughputPoint
from .sampling_study import SceneStudy
from .scenes import Regime
from .stability import StabilityMap

#: Colour-blind-safe colours (Okabe-Ito) and markers per chart series.
SERIES_STYLE: dict[str, tuple[str, str]] = {
    "rigidrel core": ("#0072B2", "star"),
    "textbook float64": ("#D55E00", "diamond"),
    "solve_ivp RK45": ("#009E73", "circle"),
    "solve_ivp DOP853": ("#56B4E9", "square"),
    "spacetimelib": ("#CC79A7", "triangle-up"),
    "mpmath 50 digits": ("#000000", "x"),
}
#: Where a series writes its first and last setting beside its markers (apart from the others).
LABEL_POSITION = {"solve_ivp RK45": "middle left", "solve_ivp DOP853": "middle right", "spacetimelib": "top center"}
#: Errors are drawn between these (a failed method at the top).
ERROR_FLOOR = 1e-17
ERROR_FAILED = 1e6
FONT = {"family": "DejaVu Sans, Arial, sans-serif", "size": 13}


def _style(series: str) -> tuple[str, str]:
    return SERIES_STYLE.get(series, ("#444444", "circle"))


def _frame_axes(fig: go.Figure, title: str) -> None:
    """The house style of every chart: boxed light-grid axes, white paper, a left title."""
    fig.update_xaxes(gridcolor="#e6e6e6", linecolor="#999", mirror=True, ticks="outside")
    fig.update_yaxes(gridcolor="#e6e6e6", linecolor="#999", mirror=True, ticks="outside")
    fig.update_layout(
        title={"text": title, "x": 0.01, "font": {"size": 17}},
        font=FONT,
        plot_bgcolor="white",
        paper_bgcolor="white",
    )


def _plotted_error(e: float | None) -> float:
    return ERROR_FAILED if e is None else min(max(e, ERROR_FLOOR), ERROR_FAILED)


def _log_ticks(lo: int, hi: int, step: int) -> tuple[list[float], list[str]]:
    vals = [10.0**k for k in range(lo, hi + 1, step)]
    return vals, [f"1e{k}" for k in range(lo, hi + 1, step)]


def speed_accuracy_figure(rows: Sequence[RegimeRow], title: str) -> go.Figure:
    """Log-log max error against seconds per sample, one panel per regime, one series per method."""
    regimes = [r for r in Regime if any(row.regime is r for row in rows)]
    cols = 3
    nrows = math.ceil(len(regimes) / cols)
    fig = make_subplots(
        rows=nrows,
        cols=cols,
        subplot_titles=[str(r) for r in regimes],
        horizontal_spacing=0.06,
        vertical_spacing=0.14,
    )
    seen: set[str] = set()
    times = [row.seconds_per_sample for row in rows if row.seconds_per_sample > 0]
    t_lo = math.floor(math.log10(min(times))) - 0.3
    t_hi = math.ceil(math.log10(max(times))) + 0.3
    for i, regime in enumerate(regimes):
        r, c = divmod(i, cols)
        series = list(dict.fromkeys(row.series for row in rows if row.regime is regime))
        for s in series:
            pts = [row for row in rows if row.regime is regime and row.series == s]
            color, symbol = _style(s)
            y = [_plotted_error(p.max_error) for p in pts]
            text = [
                f"{p.setting}: {'failed (' + p.failures[0] + ')' if p.max_error is None else f'{p.max_error:.2g}'}"
                for p in pts
            ]
            labels = [p.setting if j in (0, len(pts) - 1) and len(pts) > 1 else "" for j, p in enumerate(pts)]
            fig.add_trace(
                go.Scatter(
                    x=[p.seconds_per_sample for p in pts],
                    y=y,
                    mode="lines+markers+text" if len(pts) > 1 else "markers",
                    name=s,
                    legendgroup=s,
                    showlegend=s not in seen,
                    line={"color": color, "width": 1.5},
                    marker={
                        "color": color,
                        "symbol": [symbol if p.max_error is not None else "x-thin-open" for p in pts],
                        "size": 13 if s == "rigidrel core" else 9,
                        "line": {"color": color, "width": 2},
                    },
                    text=labels,
                    textposition=LABEL_POSITION.get(s, "top center"),
                    textfont={"size": 9, "color": color},
                    hovertext=text,
                    hoverinfo="text+name",
                ),
                row=r + 1,
                col=c + 1,
            )
            seen.add(s)
        ticks, ticktext = _log_ticks(-16, 6, 2)
        fig.update_yaxes(
            type="log",
            range=[math.log10(ERROR_FLOOR) - 0.3, math.log10(ERROR_FAILED) + 0.5],
            tickvals=[*ticks[:-1], ERROR_FAILED],
            ticktext=[*ticktext[:-1], "failed"],
            title_text="max relative error" if c == 0 else None,
            row=r + 1,
            col=c + 1,
        )
        fig.update_xaxes(
            type="log",
            range=[t_lo, t_hi],
            dtick=1,
            exponentformat="power",
            title_text="seconds per sample (wall time per call / samples)" if r == nrows - 1 else None,
            row=r + 1,
            col=c + 1,
        )
    for i in range(len(regimes)):
        axis = "" if i == 0 else str(i + 1)
        fig.add_shape(
            type="rect",
            xref=f"x{axis} domain",
            yref=f"y{axis}",
            x0=0,
            x1=1,
            y0=ERROR_FLOOR / 2.0,  # shapes take data values on log axes, annotations log10 values
            y1=ROUNDING_LEVEL,
            fillcolor="rgba(0, 114, 178, 0.10)",
            line={"width": 0},
            layer="below",
        )
        fig.add_annotation(
            xref=f"x{axis} domain",
            yref=f"y{axis}",
            x=0.99,
            y=math.log10(ROUNDING_LEVEL),
            text="float64 rounding",
            showarrow=False,
            xanchor="right",
            yanchor="bottom",
            font={"size": 10, "color": "#0072B2"},
        )
    _frame_axes(fig, title)
    fig.update_layout(
        legend={"orientation": "h", "x": 0.0, "y": -0.1, "font": {"size": 13}},
        margin={"l": 80, "r": 20, "t": 80, "b": 110},
        width=1500,
        height=420 * nrows + 180,
    )
    return fig


def _digits_label(k: float) -> str:
    v = 1.0 - 10.0 ** (-k)
    return f"{v:.3g}" if k < 2.5 else f"1−1e−{k:g}"


def _beta_label(beta: float) -> str:
    if beta == 0.0:
        return "0"
    k = -math.log10(1.0 - abs(beta))
    sign = "−" if beta < 0 else "+"
    body = f"{abs(beta):.3g}" if k < 2.5 else f"(1−1e−{round(k):g})"
    return sign + body


def stability_figure(m: StabilityMap, title: str) -> go.Figure:
    """One heatmap per method: log10 of the max error over V (x) and the frame velocity beta (y)."""
    n = len(m.series)
    fig = make_subplots(
        rows=1,
        cols=n,
        subplot_titles=[f"{s}<br><sub>{setting}</sub>" for s, setting in zip(m.series, m.settings)],
        horizontal_spacing=0.025,
        shared_yaxes=True,
    )
    x = [_digits_label(k) for k in m.velocity_digits]
    y = [_beta_label(b) for b in m.frame_velocities]
    for i, s in enumerate(m.series):
        z = [[math.log10(_plotted_error(e)) for e in row] for row in m.errors[s]]
        hover = [
            [
                f"V = {v!r}<br>beta = {b!r}<br>error = {'failed' if e is None else f'{e:.2g}'}"
                for v, e in zip(m.velocities, row)
            ]
            for b, row in zip(m.frame_velocities, m.errors[s])
        ]
        fig.add_trace(
            go.Heatmap(
                x=x,
                y=y,
                z=z,
                coloraxis="coloraxis",
                hovertext=hover,
                hoverinfo="text",
                xgap=1,
                ygap=1,
            ),
            row=1,
            col=i + 1,
        )
        fig.update_xaxes(title_text="speed of rod 1, V", tickangle=-60, type="category", row=1, col=i + 1)
    fig.update_yaxes(title_text="frame velocity β", type="category", row=1, col=1)
    fig.update_layout(
        title={"text": title, "x": 0.01, "font": {"size": 17}},
        font=FONT,
        coloraxis={
            "colorscale": "Viridis",
            "cmin": -17,
            "cmax": 0,
            "colorbar": {
                "title": {"text": "max relative<br>error", "side": "top"},
                "tickvals": list(range(-16, 1, 2)),
                "ticktext": [f"1e{k}" if k < 0 else "≥1 or failed" for k in range(-16, 1, 2)],
            },
        },
        plot_bgcolor="white",
        paper_bgcolor="white",
        margin={"l": 110, "r": 30, "t": 110, "b": 120},
        width=max(380 * n, 900),
        height=620,
    )
    return fig


def sampling_figure(studies: Sequence[SceneStudy], title: str, render_baseline: float | None = None) -> go.Figure:
    """Points used against max deviation (pixels) for fixed N and adaptive sampling, and the redraw costs."""
    rendered = render_baseline is not None and all(st.adaptive.render_seconds is not None for st in studies)
    titles = ["points drawn against max deviation", "server: rebuild all diagrams (ms)", "sent to the browser (kB)"]
    widths = [0.4, 0.2, 0.2]
    if rendered:
        titles.append("browser: draw all diagrams (ms)")
        widths = [0.34, 0.22, 0.22, 0.22]
    fig = make_subplots(rows=1, cols=len(titles), column_widths=widths, subplot_titles=titles, horizontal_spacing=0.07)
    palette = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"]
    for i, st in enumerate(studies):
        color = palette[i % len(palette)]
        fig.add_trace(
            go.Scatter(
                x=[p.points for p in st.fixed],
                y=[max(p.max_deviation_px, 1e-4) for p in st.fixed],
                mode="lines+markers",
                name=f"{st.label}: fixed N per curve",
                legendgroup=st.label,
                line={"color": color, "dash": "dot"},
                marker={"color": color, "size": 7},
                hovertext=[f"N = {p.n_fixed} per curve" for p in st.fixed],
            ),
            row=1,
            col=1,
        )
        fig.add_trace(
            go.Scatter(
                x=[st.adaptive.points],
                y=[max(st.adaptive.max_deviation_px, 1e-4)],
                mode="markers",
                name=f"{st.label}: adaptive",
                legendgroup=st.label,
                marker={"color": color, "size": 16, "symbol": "star", "line": {"color": "black", "width": 1}},
            ),
            row=1,
            col=1,
        )
    all_points = [p.points for st in studies for p in (st.adaptive, *st.fixed)]
    fig.add_trace(
        go.Scatter(
            x=[min(all_points) / 1.5, max(all_points) * 1.5],
            y=[TOLERANCE_PX, TOLERANCE_PX],
            mode="lines",
            line={"color": "#888", "dash": "dash"},
            showlegend=False,
            hoverinfo="skip",
        ),
        row=1,
        col=1,
    )
    fig.add_annotation(
        x=math.log10(max(all_points)),
        y=math.log10(TOLERANCE_PX),
        text="half a pixel",
        showarrow=False,
        yshift=9,
        xanchor="right",
        font={"size": 11, "color": "#666"},
        row=1,
        col=1,
    )
    fig.update_xaxes(type="log", title_text="points in the drawing (all curves)", row=1, col=1)
    fig.update_yaxes(type="log", title_text="max deviation from the exact curve (pixels)", row=1, col=1)
    labels = [st.short for st in studies]
    equal = [st.fixed_at_equal_accuracy(TOLERANCE_PX) for st in studies]
    largest = [st.fixed[-1] for st in studies]
    groups = (
        ("adaptive (≤ ½ px)", "#0072B2", [st.adaptive for st in studies]),
        ("fixed N: smallest within ½ px", "#E69F00", equal),
        (f"fixed N = {largest[0].n_fixed} per curve", "#D55E00", largest),
    )
    for name, color, points in groups:
        columns = [
            [1e3 * p.build_seconds for p in points],
            [p.json_bytes / 1e3 for p in points],
        ]
        if rendered and render_baseline is not None:
            columns.append([1e3 * ((p.render_seconds or 0.0) - 3 * render_baseline) for p in points])
        for j, values in enumerate(columns):
            fig.add_trace(
                go.Bar(
                    x=labels,
                    y=values,
                    name=name,
                    marker_color=color,
                    legendgroup=name,
                    showlegend=j == 0,
                    hovertext=[f"N = {p.n_fixed}" if p.n_fixed else "adaptive" for p in points],
                ),
                row=1,
                col=j + 2,
            )
    fig.update_yaxes(title_text="ms (best of repeats)", row=1, col=2)
    fig.update_yaxes(type="log", title_text="kB of figure JSON", row=1, col=3)
    if rendered:
        fig.update_yaxes(title_text="ms above an empty figure (kaleido)", row=1, col=4)
    for col in range(2, len(titles) + 1):
        fig.update_xaxes(tickangle=-30, row=1, col=col)
    _frame_axes(fig, title)
    fig.update_layout(
        barmode="group",
        legend={"orientation": "h", "x": 0.0, "y": -0.3, "font": {"size": 12}},
        margin={"l": 80, "r": 20, "t": 80, "b": 200},
        width=1600,
        height=650,
    )
    return fig


def throughput_figure(points: Sequence[ThroughputPoint], title: str) -> go.Figure:
    """Seconds per sample against samples per call, log-log: each method's fixed and marginal cost."""
    fig = go.Figure()
    for series in dict.fromkeys(p.series for p in points):
        pts = [p for p in points if p.series == series]
        color, symbol = _style(series)
        fig.add_trace(
            go.Scatter(
                x=[p.samples for p in pts],
                y=[p.seconds_per_sample for p in pts],
                mode="lines+markers",
                name=f"{series} ({pts[0].setting})",
                line={"color": color, "width": 2},
                marker={"color": color, "symbol": symbol, "size": 12 if series == "rigidrel core" else 8},
            )
        )
    fig.update_xaxes(type="log", title_text="frame times per call (samples)", exponentformat="power")
    fig.update_yaxes(type="log", title_text="seconds per sample (best call / samples)", exponentformat="power")
    _frame_axes(fig, title)
    fig.update_layout(
        legend={"x": 1.02, "y": 1.0, "font": {"size": 12}},
        margin={"l": 90, "r": 20, "t": 70, "b": 70},
        width=1100,
        height=560,
    )
    return fig
