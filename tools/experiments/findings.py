# SPDX-License-Identifier: MIT
"""Statements of where the results agree or disagree with the thesis's conclusions, computed from
the result rows. The thesis's claims are quoted; every number and verdict comes from the data."""
from collections import defaultdict

import numpy as np

THESIS_RANKING = ["zienkiewicz", "bilinear", "natural", "bezier", "coons", "voronoi"]
# A verdict rests on at least this many cases (image x vertex count x ..., as each finding says);
# below it the verdict is "not enough data", whatever the share.
MIN_CASES = 5


def ok(rows):
    return [r for r in rows if r["status"] == "ok" and r["engine"] == "reference"]


def _by_case(rows, metric):
    """{(image, nominal, colour): {method label: value}} over default variants."""
    cases = defaultdict(dict)
    for r in rows:
        if r["variant"] or r.get(metric) in (None, ""):
            continue
        cases[(r["image"], r["nominal_vertices"], r["colour"])][r["method"]] = float(r[metric])
    return cases


def _psnr(r):
    return float(r["psnr"]) if r.get("psnr") not in (None, "") else float("inf")


def verdict(fraction, cases, strong=0.75):
    """The verdict on a share `fraction` of `cases` cases that agree with the thesis."""
    if fraction is None or not cases:
        return "no data"
    if cases < MIN_CASES:
        return "not enough data"
    if fraction >= strong:
        return "agrees"
    if fraction > 0.5:
        return "mostly agrees"
    if fraction >= 1 - strong:
        return "mixed"
    return "disagrees"


def compare_pair(rows, better, worse, metric):
    cases = _by_case(rows, metric)
    wins = total = 0
    diffs = []
    for values in cases.values():
        if better in values and worse in values:
            total += 1
            d = values[better] - values[worse]
            if metric == "mse":
                d = -d
            diffs.append(d)
            wins += d > 0
    return wins, total, (float(np.mean(diffs)) if diffs else None)


def mean_ranks(rows, metric, methods):
    """({method: mean rank over the cases}, number of cases ranked)."""
    cases = _by_case(rows, metric)
    ranks = defaultdict(list)
    ranked = 0
    for values in cases.values():
        present = [m for m in methods if m in values]
        if len(present) < 2:
            continue
        ranked += 1
        order = sorted(present, key=lambda m: values[m], reverse=(metric != "mse"))
        for i, m in enumerate(order):
            ranks[m].append(i + 1)
    return {m: float(np.mean(v)) for m, v in ranks.items()}, ranked


def about_image(claim_image, rows):
    """None when the thesis's claim is about an image the rows have (or about none), else a
    verdict saying the comparison is with other images."""
    if claim_image is None or any(r["image"] == claim_image for r in rows):
        return None
    return f"not comparable (the claim is about {claim_image.capitalize()}, not in this set)"


def grey_findings(grey_rows):
    out = []
    rows = ok(grey_rows)
    high = [r for r in rows if r["nominal_vertices"] >= 10000]
    scope, scope_rows = ("at 10,000 and 15,000 vertices", high) if high else ("at every vertex count run", rows)
    for metric, name in (("psnr", "PSNR"), ("ssim", "SSIM")):
        wins, total, mean_d = compare_pair(scope_rows, "zienkiewicz", "bilinear", metric)
        all_wins, all_total, _ = compare_pair(rows, "zienkiewicz", "bilinear", metric)
        frac = wins / total if total else None
        unit = " dB" if metric == "psnr" else ""
        out.append({
            "topic": f"Zienkiewicz against bilinear ({name})",
            "thesis": "Zienkiewicz outperforms bilinear (and every other method) on every tested image at "
                      "10,000 and 15,000 vertices (6.1.1, 7).",
            "here": (f"{scope.capitalize()}, Zienkiewicz has the higher {name} in {wins} of {total} greyscale "
                     f"cases (image x vertex count); mean difference {mean_d:+.3f}{unit}. Over all counts: "
                     f"{all_wins} of {all_total}." if total else "no cases with both methods"),
            "cases": total, "verdict": verdict(frac, total)})
    # Voronoi: the thesis's "complete failure".
    for metric, name in (("psnr", "PSNR"),):
        cases = _by_case(rows, metric)
        worst = total = 0
        for values in cases.values():
            if "voronoi" in values and len(values) > 2:
                total += 1
                worst += values["voronoi"] <= min(values.values())
        if total:
            out.append({"topic": "Voronoi (piecewise linear on the Voronoi diagram)",
                        "thesis": "A complete failure: the worst method by every measure (6.1.1, 7).",
                        "here": f"Voronoi has the lowest {name} of all methods in {worst} of {total} greyscale "
                                f"cases.",
                        "cases": total, "verdict": verdict(worst / total, total)})
    # Ranking by mean rank over cases.
    for metric, name in (("psnr", "PSNR"), ("ssim", "SSIM")):
        f = ranking_finding(rows, metric, name, "greyscale cases",
                            "Zienkiewicz >= bilinear > natural neighbour > Bezier > Coons > Voronoi.",
                            topic=f"Ranking of the methods ({name})")
        if f:
            out.append(f)
    # 30 dB thresholds.
    for nominal, claim, claim_image in ((5000, "PSNR reaches 30 dB at about 5,000 vertices (Fruits, figure 6.11)",
                                         "fruits"),
                                        (10000, "with 10,000 vertices PSNR usually goes over 30 dB", None)):
        best = defaultdict(float)
        for r in rows:
            if r["nominal_vertices"] == nominal and r["method"] in ("bilinear", "zienkiewicz") and not r["variant"]:
                best[r["image"]] = max(best[r["image"]], _psnr(r))
        if best:
            over = sum(v >= 30 for v in best.values())
            out.append({"topic": f"30 dB at {nominal:,} vertices",
                        "thesis": claim + ".",
                        "here": f"{over} of {len(best)} greyscale images reach 30 dB at {nominal:,} vertices "
                                f"(thesis scale) with the better of bilinear and Zienkiewicz "
                                f"(median {np.median(list(best.values())):.2f} dB).",
                        "cases": len(best),
                        "verdict": about_image(claim_image, rows) or verdict(over / len(best), len(best))})
    # SSIM at 1,000 vertices with the thesis's 8x8 window.
    vals = [float(r["ssim_8x8"]) for r in rows if r["nominal_vertices"] == 1000 and not r["variant"]
            and r.get("ssim_8x8") not in (None, "") and r["method"] in ("bilinear", "zienkiewicz")]
    if vals:
        inside = sum(0.5 <= v <= 0.7 for v in vals)
        out.append({"topic": "SSIM at 1,000 vertices",
                    "thesis": "SSIM 0.5 to 0.7 at 1,000 vertices (Lena, 8x8 windows; flat images over 0.8).",
                    "here": f"8x8-window SSIM of bilinear and Zienkiewicz at 1,000 vertices ranges "
                            f"{min(vals):.3f} to {max(vals):.3f} (median {np.median(vals):.3f}); "
                            f"{inside} of {len(vals)} values lie in 0.5-0.7.",
                    "cases": len(vals),
                    "verdict": about_image("lena", rows) or verdict(inside / len(vals), len(vals))})
    # Diminishing returns from 10,000 to 15,000.
    by = defaultdict(dict)
    for r in rows:
        if r["method"] == "zienkiewicz" and not r["variant"]:
            by[r["image"]][r["nominal_vertices"]] = _psnr(r)
    g1 = [v[10000] - v[5000] for v in by.values() if 5000 in v and 10000 in v and np.isfinite(v[10000])]
    g2 = [v[15000] - v[10000] for v in by.values() if 10000 in v and 15000 in v and np.isfinite(v[15000])]
    if g1 and g2:
        smaller = sum(b < a for a, b in zip(g1, g2))
        out.append({"topic": "10,000 against 15,000 vertices",
                    "thesis": "The differences between 10,000 and 15,000 vertices are small (figure 6.11).",
                    "here": f"Zienkiewicz PSNR gains {np.mean(g2):.2f} dB from 10,000 to 15,000 against "
                            f"{np.mean(g1):.2f} dB from 5,000 to 10,000 (mean over {len(g2)} images); the "
                            f"second step gains less on {smaller} of {len(g2)} images.",
                    "cases": len(g2), "verdict": verdict(smaller / len(g2), len(g2))})
    # Patch artifacts where small and large triangles meet.
    for patch in ("bezier", "coons"):
        for variant in ("", "thesis"):
            agree = total = 0
            hi_ratio, lo_ratio = [], []
            cases = defaultdict(dict)
            for r in rows:
                if r.get("mae_high") in (None, "") or r["variant"] not in ("", variant):
                    continue
                if r["method"] == patch and r["variant"] == variant:
                    cases[(r["image"], r["nominal_vertices"])]["p"] = r
                elif r["method"] == "bilinear" and not r["variant"]:
                    cases[(r["image"], r["nominal_vertices"])]["b"] = r
            for c in cases.values():
                if "p" in c and "b" in c and float(c["b"]["mae_high"]) > 0 and float(c["b"]["mae_low"]) > 0:
                    h = float(c["p"]["mae_high"]) / float(c["b"]["mae_high"])
                    lo = float(c["p"]["mae_low"]) / float(c["b"]["mae_low"])
                    hi_ratio.append(h)
                    lo_ratio.append(lo)
                    total += 1
                    agree += h > lo
            if not total:
                continue
            label = patch + (" (thesis variant)" if variant else "")
            out.append({"topic": f"Artifacts where triangle sizes meet: {label}",
                        "thesis": "The patch methods show artifacts where triangles of very different sizes meet "
                                  "(6.1.1, figure 6.5; worse for Coons).",
                        "here": f"Mean absolute error of {label} relative to bilinear is {np.mean(hi_ratio):.3f}x in "
                                f"triangles whose area differs most from a neighbour's (top 10% of area ratio) and "
                                f"{np.mean(lo_ratio):.3f}x in the most uniform half; higher in the mixed-size "
                                f"triangles in {agree} of {total} cases.",
                        "cases": total, "verdict": verdict(agree / total, total)})
    return out


def ranking_finding(rows, metric, name, scope, thesis_text, topic=None):
    present = sorted({r["method"] for r in rows if not r["variant"]})
    ranks, ranked = mean_ranks(rows, metric, [m for m in THESIS_RANKING if m in present])
    if len(ranks) < 2:
        return None
    ours = sorted(ranks, key=ranks.get)
    expected = [m for m in THESIS_RANKING if m in ranks]
    pairs = agree = 0
    reversed_pairs = []
    for i in range(len(expected)):
        for j in range(i + 1, len(expected)):
            pairs += 1
            if ranks[expected[i]] <= ranks[expected[j]]:
                agree += 1
            else:
                reversed_pairs.append(f"{expected[j]} ahead of {expected[i]}")
    missing = [m for m in THESIS_RANKING if m not in ranks]
    text = (f"Mean rank by {name} over the {scope}: " + ", ".join(f"{m} {ranks[m]:.2f}" for m in ours)
            + f". {agree} of {pairs} pairs in the thesis's order"
            + (f"; reversed: {', '.join(reversed_pairs)}" if reversed_pairs else "")
            + (f". Not built, so not ranked: {', '.join(missing)}" if missing else "") + ".")
    topic = topic or f"Ranking of the methods, {scope.split(' (')[0]} ({name})"
    return {"topic": topic, "thesis": thesis_text, "here": text, "cases": ranked,
            "verdict": verdict(agree / pairs if pairs else None, ranked)}


def colour_findings(colour_rows):
    out = []
    rows = [r for r in ok(colour_rows) if not r["variant"] and r["study"] == "colour"]
    f = ranking_finding(rows, "psnr", "PSNR", "colour cases (image x total x triangulation)",
                        "On colour images Zienkiewicz and bilinear are still the best, followed closely by natural "
                        "neighbour (6.1.2, figure 6.12).")
    if f:
        out.append(f)
    idx = {(r["image"], r["nominal_vertices"], r["mode"], r["space"], r["cotri"], r["method"]): r for r in rows}
    for metric, name in (("psnr", "PSNR"), ("ssim", "SSIM")):
        sep_wins = total = 0
        diffs = []
        for (image, nominal, mode, space, cotri, method), r in idx.items():
            if mode != "separate":
                continue
            co = idx.get((image, nominal, "co", space, "greedy", method))
            if co is None:
                continue
            a = _psnr(r) if metric == "psnr" else float(r[metric])
            b = _psnr(co) if metric == "psnr" else float(co[metric])
            if not (np.isfinite(a) and np.isfinite(b)):
                continue
            total += 1
            sep_wins += a > b
            diffs.append(a - b)
        if not total:
            continue
        claim = ("PSNR is better for separate triangulations (Yacht, Baboon), though not for every image "
                 "(6.1.3)." if metric == "psnr" else
                 "SSIM is better for co-triangulations for Yacht and Baboon, not for Lena and Peppers (6.1.3).")
        frac = sep_wins / total if metric == "psnr" else 1 - sep_wins / total
        out.append({"topic": f"Separate against co-triangulation, equal totals ({name})",
                    "thesis": claim,
                    "here": f"At equal total vertex counts, separate triangulations have the higher {name} in "
                            f"{sep_wins} of {total} cases (image x total x space x method); mean "
                            f"separate - co {np.mean(diffs):+.3f}{' dB' if metric == 'psnr' else ''}.",
                    "cases": total, "verdict": verdict(frac, total)})
    # Co-triangulations need fewer vertices.
    co_better = total = 0
    for (image, nominal, mode, space, cotri, method), r in idx.items():
        if mode == "co" and cotri == "greedy" and method in ("bilinear", "zienkiewicz"):
            s = idx.get((image, nominal, "separate", space, "", method))
            if s is not None:
                total += 1
                co_better += _psnr(r) >= _psnr(s)
    if total:
        out.append({"topic": "Compression: co-triangulation against separate",
                    "thesis": "Co-triangulations reach similar PSNR and SSIM with significantly fewer vertices "
                              "than separate triangulations (6.1.3, 7).",
                    "here": f"With the same total number of vertices, the co-triangulation is at least as good in "
                            f"PSNR in {co_better} of {total} cases (bilinear and Zienkiewicz).",
                    "cases": total, "verdict": verdict(co_better / total, total)})
    for metric, name in (("psnr", "PSNR"), ("ssim", "SSIM")):
        rgb_wins = total = 0
        diffs = []
        for (image, nominal, mode, space, cotri, method), r in idx.items():
            if space != "rgb" or cotri not in ("", "greedy"):
                continue
            y = idx.get((image, nominal, mode, "ycbcr", cotri, method))
            if y is None:
                continue
            a = _psnr(r) if metric == "psnr" else float(r[metric])
            b = _psnr(y) if metric == "psnr" else float(y[metric])
            if not (np.isfinite(a) and np.isfinite(b)):
                continue
            total += 1
            rgb_wins += a > b
            diffs.append(a - b)
        if total:
            out.append({"topic": f"RGB against YCbCr ({name})",
                        "thesis": "The differences are minor but RGB is slightly better at equal vertex counts "
                                  "(Yacht, figure 6.14); YCbCr compresses better.",
                        "here": f"RGB has the higher {name} in {rgb_wins} of {total} cases (same image, total, "
                                f"mode and method); mean RGB - YCbCr {np.mean(diffs):+.3f}"
                                f"{' dB' if metric == 'psnr' else ''}.",
                        "cases": total, "verdict": verdict(rgb_wins / total, total)})
    # Figure 6.13: the Y layer's count matters more than Cb/Cr's.
    split = [r for r in ok(colour_rows) if r["study"] == "split" and not r["variant"]]
    by = defaultdict(dict)
    for r in split:
        by[(r["image"], r["method"])][r["colour"]] = _psnr(r)
    gy, gc = [], []
    for values in by.values():
        keys = {k: v for k, v in values.items()}
        def get(y, c):
            for k, v in keys.items():
                if k.endswith(f"Y{y}/C{c}"):
                    return v
            return None
        ys = sorted({int(k.split("Y")[1].split("/")[0]) for k in keys})
        cs = sorted({int(k.split("/C")[1]) for k in keys})
        if len(ys) == 2 and len(cs) == 2:
            for c in cs:
                a, b = get(ys[0], c), get(ys[1], c)
                if a is not None and b is not None:
                    gy.append(b - a)
            for y in ys:
                a, b = get(y, cs[0]), get(y, cs[1])
                if a is not None and b is not None:
                    gc.append(b - a)
    if gy and gc:
        out.append({"topic": "YCbCr: vertices in Y against Cb/Cr",
                    "thesis": "Raising the Y triangulation from 3,000 to 7,000 vertices matters much more than "
                              "raising Cb and Cr from 1,000 to 20,000 each (figure 6.13).",
                    "here": f"Mean PSNR gain {np.mean(gy):+.2f} dB from more Y vertices against {np.mean(gc):+.2f} dB "
                            f"from more Cb/Cr vertices (over images and methods); the Y step is the larger in "
                            f"{sum(a > b for a, b in zip(gy, gc))} of {len(gy)} pairs. 'Much more' is taken as at "
                            f"least twice the gain.",
                    "cases": len(gy),
                    "verdict": ("not enough data" if len(gy) < MIN_CASES else
                                "agrees" if np.mean(gy) >= 2 * max(np.mean(gc), 0) else
                                "mostly agrees" if np.mean(gy) > np.mean(gc) else "disagrees")})
    return out


def time_findings(table, thesis, images):
    """table: {method label: {vertices: seconds}}; thesis: same for the thesis; images: {vertices:
    the number of images behind the means}. A case is an image timed at the compared count."""
    out = []
    counts = sorted({n for v in table.values() for n in v})
    if not counts:
        return out
    both = [c for c in counts if c in table.get("bilinear", {}) and c in thesis.get("bilinear", {})]
    n = max(both) if both else max(counts)
    ours = {m: v[n] for m, v in table.items() if n in v}
    order = sorted(ours, key=ours.get)
    thesis_order = sorted((m for m in thesis if n in thesis[m]), key=lambda m: thesis[m][n])
    comparable = [m for m in thesis_order if m in ours or m + " (thesis)" in ours]

    def ours_of(m):
        return ours.get(m + " (thesis)", ours.get(m))
    agree = pairs = 0
    for i in range(len(comparable)):
        for j in range(i + 1, len(comparable)):
            pairs += 1
            agree += ours_of(comparable[i]) <= ours_of(comparable[j])
    out.append({"topic": f"Speed order at {n:,} vertices",
                "thesis": "Bilinear < Zienkiewicz < Voronoi < natural neighbour < Bezier < Coons (figure 6.22).",
                "here": "Here: " + " < ".join(f"{m} {ours[m]:.3g} s" for m in order)
                        + f". {agree} of {pairs} pairs of the thesis's methods in its order (patch methods "
                          f"compared through their thesis variants where run).",
                "cases": images.get(n, 0), "verdict": verdict(agree / pairs if pairs else None, images.get(n, 0))})
    if "bilinear" in ours and "zienkiewicz" in ours:
        ratio = ours["zienkiewicz"] / ours["bilinear"]
        t_ratio = thesis["zienkiewicz"][n] / thesis["bilinear"][n] if n in thesis.get("bilinear", {}) else None
        out.append({"topic": "Cost of Zienkiewicz over bilinear",
                    "thesis": "Zienkiewicz is only a few hundredths of a second slower than bilinear"
                              + (f" ({t_ratio:.2f}x at {n:,} vertices)." if t_ratio else "."),
                    "here": f"Zienkiewicz takes {ratio:.2f}x the time of bilinear at {n:,} vertices "
                            f"({ours['zienkiewicz'] - ours['bilinear']:+.3f} s); within 2x counts as agreement.",
                    "cases": images.get(n, 0), "verdict": verdict(1.0 if ratio <= 2 else 0.0, images.get(n, 0))})
    return out
