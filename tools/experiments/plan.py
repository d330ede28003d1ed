# SPDX-License-Identifier: MIT
"""What the quick and the full experiment sets contain.

Vertex counts follow the thesis (section 6.1.1): 1,000 to 15,000 vertices for a 512x512 image.
Images of another size get the count scaled by their area, n = round(N * W * H / 512^2), so the
density of vertices per pixel is the thesis's; the report states both counts.
"""
from dataclasses import dataclass, field
from pathlib import Path
from typing import List, Optional, Tuple

THESIS_AREA = 512 * 512
GREY_COUNTS = [1000, 2000, 5000, 10000, 15000]
# Colour: total vertex counts (all channels together) for a 512x512 image. A co-triangulation
# gets the total; separate triangulations get a third of it each, so the totals are equal.
COLOUR_TOTALS = [3000, 6000, 15000, 30000]
# Section 6.1.2, figure 6.13: Y against Cb/Cr vertex counts of separate YCbCr triangulations.
YCBCR_SPLITS = [(3000, 1000), (3000, 20000), (7000, 1000), (7000, 20000)]
# Figure 6.22's vertex counts (512x512 images).
TIME_COUNTS = [2000, 4000, 5000, 7000, 10000, 12000, 15000]
# Methods whose 'thesis' variant (the thesis's step sampling) is run besides the default.
THESIS_VARIANTS = ("bezier", "coons")
# Kodak images of the full set's greyscale part (every fourth, plus the demo's kodim23).
KODAK_GREY = ("kodim23",)
# Colour images of the full set: the thesis's (Yacht = sailboat, Baboon = mandrill, Peppers, Airplane,
# Fruits); Lena and Pool are not available.
COLOUR_IMAGES = ("sailboat", "mandrill", "peppers", "airplane", "fruits")


def scaled(n_nominal: int, width: int, height: int) -> int:
    return max(4, int(round(n_nominal * width * height / THESIS_AREA)))


@dataclass(frozen=True)
class Source:
    name: str          # display name, unique in a run
    path: Path         # the file on disk
    group: str         # demo, grey, colour or kodak
    width: int
    height: int
    channels: int      # 1 or 3
    crop: Optional[Tuple[int, int, int, int]] = None  # x, y, w, h of a derived crop


@dataclass(frozen=True)
class Enc:
    """One triangulation to make: triencode's options on one input."""
    study: str               # grey, colour, split or time
    image: str               # display name of the source
    group: str
    source: Source
    grey: bool               # encode (and compare) the luma of the image
    mode: str                # grey, co, separate or split (a composed separate YCbCr file)
    space: str               # grey, rgb or ycbcr
    n: int                   # triencode -n (per channel for separate)
    nominal: int             # the thesis-scale count (total for colour)
    cotri: str = "greedy"
    parts: Tuple = ()        # split: (n of the Y layer, n of the Cb and Cr layers), scaled
    parts_nominal: Tuple = ()  # split: the same at thesis scale

    @property
    def label(self):
        if self.mode == "grey":
            return "grey"
        if self.mode == "split":
            return f"separate-{self.space} Y{self.parts_nominal[0]}/C{self.parts_nominal[1]}"
        suffix = "" if self.mode != "co" or self.cotri == "greedy" else f"-{self.cotri}"
        return f"{self.mode}-{self.space}{suffix}"


@dataclass
class Plan:
    name: str
    grey_sources: List[Source] = field(default_factory=list)
    colour_sources: List[Source] = field(default_factory=list)
    time_sources: List[Source] = field(default_factory=list)
    grey_counts: List[int] = field(default_factory=list)
    colour_totals: List[int] = field(default_factory=list)
    cotri_thesis_totals: List[int] = field(default_factory=list)
    splits: List[Tuple[int, int]] = field(default_factory=list)
    split_sources: List[Source] = field(default_factory=list)
    time_counts: List[int] = field(default_factory=list)
    time_repeats: int = 3
    thesis_variants_for: List[str] = field(default_factory=list)   # grey source names
    picture_cases: List[Tuple[str, str, int]] = field(default_factory=list)  # (image, label, nominal)
    notes: List[str] = field(default_factory=list)


def read_size(path: Path):
    from PIL import Image
    with Image.open(path) as im:
        channels = 1 if im.mode in ("L", "I;16", "I", "1") else 3
        if im.mode not in ("L", "RGB"):
            raise ValueError(f"{path}: expected an 8-bit greyscale or RGB PNG, found mode {im.mode}")
        return im.size[0], im.size[1], channels


def source(name, path, group, crop=None):
    w, h, c = read_size(path)
    if crop:
        w, h = crop[2], crop[3]
    return Source(name, Path(path), group, w, h, c, crop)


def shared_sources(images_dir: Optional[Path], notes: List[str]):
    """The photographs under images_dir (grey/, colour/, kodak/); empty lists with a note when absent."""
    found = {"grey": [], "colour": [], "kodak": []}
    if images_dir is None:
        notes.append("No test photographs given (--images DIR or TRISTREAM_IMAGES): the experiments that use "
                     "them were skipped.")
        return found
    if not images_dir.is_dir():
        notes.append(f"The shared test images ({images_dir}) are absent: the experiments that use them were "
                     f"skipped.")
        return found
    for group in found:
        folder = images_dir / group
        if not folder.is_dir():
            notes.append(f"{folder} is absent: its images were skipped.")
            continue
        for p in sorted(folder.glob("*.png")):
            found[group].append(source(p.stem, p, group))
    return found


def make_plan(name: str, repo: Path, images_dir: Optional[Path]) -> Plan:
    demo = source("kodim23", repo / "data/demo/kodim23.png", "demo")
    if name == "quick":
        plan = Plan("quick")
        plan.notes.append("Quick set: only the Kodak image shipped in data/demo (kodim23, 768x512); "
                          "the shared test images are not used.")
        crop = source("kodim23-crop512", demo.path, "demo", crop=(128, 0, 512, 512))
        plan.grey_sources = [demo]
        plan.grey_counts = [1000, 2000, 5000]
        plan.colour_sources = [demo]
        plan.colour_totals = [3000, 6000, 15000]
        plan.cotri_thesis_totals = [6000]
        plan.split_sources = [demo]
        plan.splits = YCBCR_SPLITS
        plan.time_sources = [crop]
        plan.time_counts = [2000, 5000, 10000]
        plan.time_repeats = 2
        plan.thesis_variants_for = []
        plan.picture_cases = [("kodim23", "grey", 2000), ("kodim23", "co-rgb", 6000),
                              ("kodim23", "separate-rgb", 6000)]
        return plan
    if name != "full":
        raise ValueError(f"unknown set '{name}' (expected quick or full)")
    plan = Plan("full")
    shared = shared_sources(images_dir, plan.notes)
    kodak_grey = [s for s in shared["kodak"] if s.name in KODAK_GREY]
    plan.grey_sources = shared["grey"] + shared["colour"] + kodak_grey
    if kodak_grey:
        plan.notes.append(f"Kodak images used as greyscale: {len(kodak_grey)} of {len(shared['kodak'])} "
                          f"({', '.join(s.name for s in kodak_grey)}), to keep the full set within about an hour "
                          f"on two shared cores; the other Kodak images can be added to KODAK_GREY in plan.py.")
    if not plan.grey_sources:
        plan.grey_sources = [demo]
        plan.notes.append("The full set fell back on data/demo/kodim23.png for greyscale.")
    plan.grey_counts = GREY_COUNTS
    plan.colour_sources = [s for s in shared["colour"] if s.name in COLOUR_IMAGES] or [demo]
    plan.colour_totals = COLOUR_TOTALS[:3]
    plan.notes.append(f"Colour: the thesis's images that are available ({', '.join(COLOUR_IMAGES)}) at totals "
                      f"{', '.join(f'{n:,}' for n in plan.colour_totals)} (thesis scale).")
    plan.cotri_thesis_totals = [15000]
    plan.split_sources = [s for s in plan.colour_sources if s.name in ("sailboat", "peppers", "mandrill")] \
        or [demo]
    plan.splits = YCBCR_SPLITS
    timing = [s for s in shared["grey"] if s.name in ("boat", "goldhill")]
    plan.time_sources = timing or [source("kodim23-crop512", demo.path, "demo", crop=(128, 0, 512, 512))]
    plan.time_counts = TIME_COUNTS
    plan.time_repeats = 2
    # The thesis variants cost seconds per image (step sampling): run on the timing images only.
    plan.thesis_variants_for = [s.name for s in plan.time_sources]
    names = {s.name for s in plan.grey_sources} | {s.name for s in plan.colour_sources}
    wanted = [("boat", "grey", 5000), ("fruits", "grey", 5000), ("peppers", "co-rgb", 15000),
              ("peppers", "separate-rgb", 15000), ("kodim23", "grey", 2000)]
    plan.picture_cases = [c for c in wanted if c[0] in names] or [("kodim23", "grey", 2000)]
    return plan
