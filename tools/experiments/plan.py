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
# The images the full set reads from --images DIR: every file of these types under DIR (its grey/,
# colour/ and kodak/ folders, or any other layout), greyscale as it is, colour also as luma.
IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg", ".bmp", ".pnm", ".pgm", ".ppm")
# Figure 6.22's timing runs use these 512x512 greyscale photographs when present (the thesis's
# Boat and Goldhill), else the first greyscale image of DIR, else a 512x512 crop of the demo image.
TIMING_IMAGES = ("boat", "goldhill")
# Colour images split by Y/Cb/Cr allocation (figure 6.13): the thesis's when present, else all.
SPLIT_IMAGES = ("sailboat", "peppers", "mandrill")


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
        if im.mode not in ("L", "RGB"):
            raise ValueError(f"{path}: expected an 8-bit greyscale or RGB image, found mode {im.mode}")
        return im.size[0], im.size[1], 1 if im.mode == "L" else 3


def source(name, path, group, crop=None):
    w, h, c = read_size(path)
    if crop:
        w, h = crop[2], crop[3]
    return Source(name, Path(path), group, w, h, c, crop)


def shared_sources(images_dir: Path, notes: List[str]) -> List[Source]:
    """Every image under images_dir (IMAGE_SUFFIXES, any depth), named by its file name without the
    suffix (by its path under images_dir when two share a name), grouped by its first folder (kodak,
    grey, colour, ...; "images" at the top). Images that cannot be used are listed in the notes.
    ValueError when images_dir is not a folder or holds no usable image."""
    if not images_dir.is_dir():
        raise ValueError(f"{images_dir}: no such folder (--images DIR or TRISTREAM_IMAGES)")
    files = sorted(p for p in images_dir.rglob("*") if p.is_file() and p.suffix.lower() in IMAGE_SUFFIXES)
    stems = [p.stem for p in files]
    found, skipped = [], []
    for p in files:
        rel = p.relative_to(images_dir)
        name = p.stem if stems.count(p.stem) == 1 else rel.with_suffix("").as_posix()
        group = rel.parts[0] if len(rel.parts) > 1 else "images"
        try:
            found.append(source(name, p, group))
        except (OSError, ValueError) as exc:
            skipped.append(f"{rel} ({exc.__class__.__name__}: {str(exc).replace(str(p) + ': ', '')})")
    if skipped:
        notes.append(f"Images of {images_dir} not used: {'; '.join(skipped)}.")
    if not found:
        raise ValueError(f"{images_dir}: no usable image ({', '.join(IMAGE_SUFFIXES)}; 8-bit greyscale or RGB) "
                         f"in it or its folders" + (f"; skipped: {'; '.join(skipped)}" if skipped else ""))
    return found


def names(sources: List[Source]) -> str:
    return ", ".join(s.name for s in sources)


def count(sources: List[Source]) -> str:
    return f"{len(sources)} image" + ("" if len(sources) == 1 else "s")


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
    crop = source("kodim23-crop512", demo.path, "demo", crop=(128, 0, 512, 512))
    if images_dir is None:
        plan.notes.append("No test photographs given (--images DIR or TRISTREAM_IMAGES): the full set ran on "
                          "the shipped demo image (data/demo/kodim23.png) alone.")
        shared = [demo]
    else:
        shared = shared_sources(images_dir, plan.notes)
    grey = [s for s in shared if s.channels == 1]
    colour = [s for s in shared if s.channels == 3]
    plan.grey_sources = grey + colour
    plan.grey_counts = GREY_COUNTS
    plan.notes.append(f"Greyscale: {count(plan.grey_sources)} ({names(grey) or 'none'} as they are"
                      + (f"; {names(colour)} as luma" if colour else "") + ").")
    plan.colour_sources = colour
    plan.colour_totals = COLOUR_TOTALS[:3]
    plan.cotri_thesis_totals = [15000]
    plan.split_sources = [s for s in colour if s.name in SPLIT_IMAGES] or colour
    plan.splits = YCBCR_SPLITS
    if colour:
        plan.notes.append(f"Colour: {count(colour)} ({names(colour)}) at totals "
                          f"{', '.join(f'{n:,}' for n in plan.colour_totals)} (thesis scale); the Y/Cb/Cr "
                          f"allocations on {names(plan.split_sources)}.")
    else:
        plan.notes.append("Colour: no colour image among the photographs, so no colour study.")
    plan.time_sources = [s for s in grey if s.name in TIMING_IMAGES] or grey[:1] or [crop]
    plan.notes.append(f"Time: {names(plan.time_sources)}.")
    plan.time_counts = TIME_COUNTS
    plan.time_repeats = 2
    # The thesis variants cost seconds per image (step sampling): run on the timing images only.
    plan.thesis_variants_for = [s.name for s in plan.time_sources]
    wanted = [("boat", "grey", 5000), ("fruits", "grey", 5000), ("peppers", "co-rgb", 15000),
              ("peppers", "separate-rgb", 15000), ("kodim23", "grey", 2000)]
    known = {s.name for s in plan.grey_sources} | {s.name for s in plan.colour_sources}
    plan.picture_cases = [c for c in wanted if c[0] in known] or [(plan.grey_sources[0].name, "grey", 2000)]
    return plan
