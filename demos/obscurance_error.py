#!/usr/bin/python3
"""Error of every volumetric obscurance mode against the converged reference, from the
`vo_show 1` screenshots demos/bench_obscurance.sh takes (grey = obscurance, 1 = open).

For each mode and sample set: RMSE and SSIM against `reference` (a: the depth buffer's own
converged obscurance) and against `raytraced` (b: vo_reference, the real geometry) on the still
frames (mean over them), and
flicker over the stretch of consecutive frames: the mean absolute frame-to-frame change of the
mode's obscurance minus the reference's own (what the camera's motion explains). Prints a
Markdown table. numpy and Pillow come with Debian's python3-matplotlib."""
import argparse
import sys

import numpy as np
from PIL import Image, ImageDraw


def load(shots, mode, frame):
    path = f"{shots}/{mode}_{frame}.png"
    try:
        return np.asarray(Image.open(path).convert("L"), dtype=np.float64) / 255.0
    except OSError as error:
        sys.exit(f"obscurance_error.py: cannot read {path}: {error}")


def gaussian_blur(image, sigma=1.5, radius=5):
    x = np.arange(-radius, radius + 1)
    kernel = np.exp(-0.5 * (x / sigma) ** 2)
    kernel /= kernel.sum()
    rows = np.apply_along_axis(lambda r: np.convolve(r, kernel, mode="valid"), 1, image)
    return np.apply_along_axis(lambda c: np.convolve(c, kernel, mode="valid"), 0, rows)


def ssim(a, b):
    """Wang et al. 2004 with an 11-tap Gaussian window (sigma 1.5), K1 0.01, K2 0.03, L 1."""
    c1, c2 = 0.01**2, 0.03**2
    mu_a, mu_b = gaussian_blur(a), gaussian_blur(b)
    var_a = gaussian_blur(a * a) - mu_a**2
    var_b = gaussian_blur(b * b) - mu_b**2
    cov = gaussian_blur(a * b) - mu_a * mu_b
    index = ((2 * mu_a * mu_b + c1) * (2 * cov + c2)) / (
        (mu_a**2 + mu_b**2 + c1) * (var_a + var_b + c2))
    return float(index.mean())


def flicker(frames):
    return float(np.mean([np.abs(b - a).mean() for a, b in zip(frames, frames[1:])]))


def contact_sheet(shots, frame, names, output):
    """The frame's obscurance in each named configuration, side by side, labelled."""
    tiles = []
    for name in names:
        image = Image.open(f"{shots}/{name}_{frame}.png").convert("RGB").resize((320, 240))
        ImageDraw.Draw(image).text((6, 4), name, fill=(200, 0, 0))
        tiles.append(image)
    sheet = Image.new("RGB", (320 * len(tiles), 240), (255, 255, 255))
    for i, tile in enumerate(tiles):
        sheet.paste(tile, (320 * i, 0))
    sheet.save(output, quality=85)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--shots", required=True)
    parser.add_argument("--configs", required=True,
                        help="space-separated shot names (mode, mode_poisson, ...), one reference")
    parser.add_argument("--stills", required=True, help="space-separated frame numbers")
    parser.add_argument("--stretch", required=True, help="consecutive frame numbers")
    parser.add_argument("--sheets", help="folder for one contact sheet per still frame")
    args = parser.parse_args()
    modes = [m for m in args.configs.split() if m != "reference"]
    stills, stretch = args.stills.split(), args.stretch.split()
    reference = {f: load(args.shots, "reference", f) for f in stills + stretch}
    reference_flicker = flicker([reference[f] for f in stretch])
    print(f"Against `reference` (64 x 64 stratified lines) on demo.dem frames {', '.join(stills)}"
          f" (640x480, blur on); flicker over frames {stretch[0]}-{stretch[-1]}, the "
          f"reference's own frame-to-frame change ({reference_flicker:.4f}) subtracted.\n")
    raytraced = {f: load(args.shots, "raytraced", f) for f in stills}
    print("| mode, sample set | RMSE (a) | SSIM (a) | RMSE (b) | SSIM (b) | flicker |")
    print("| --- | --- | --- | --- | --- | --- |")

    def errors(images, against):
        rmse = np.mean([np.sqrt(np.mean((images[f] - against[f]) ** 2)) for f in stills])
        return rmse, np.mean([ssim(images[f], against[f]) for f in stills])

    rmse_b, ssim_b = errors(reference, raytraced)
    print(f"| reference (a) | 0 | 1 | {rmse_b:.4f} | {ssim_b:.4f} | 0 |")
    for mode in modes:
        images = {f: load(args.shots, mode, f) for f in stills}
        rmse, similarity = errors(images, reference)
        rmse_b, ssim_b = errors(images, raytraced)
        excess = flicker([load(args.shots, mode, f) for f in stretch]) - reference_flicker
        name = mode.replace("_", ", ") if "_" in mode else f"{mode}, electrostatic"
        if mode == "area1":
            name = "area1"
        print(f"| {name} | {rmse:.4f} | {similarity:.4f} | {rmse_b:.4f} | {ssim_b:.4f} "
              f"| {excess:+.4f} |")
    if args.sheets:
        for f in stills:
            contact_sheet(args.shots, f, ["lines5", "points12", "area1", "reference", "raytraced"],
                          f"{args.sheets}/error_frame_{f}.jpg")


if __name__ == "__main__":
    main()
