#!/usr/bin/env python3
"""Draws a render-audio WAV with the shot's events marked, as SVG (standard library only).

    billiards render-audio assets/scenes/eight-ball-break.json --out break.wav
    billiards simulate assets/scenes/eight-ball-break.json --out break.json
    python3 docs/sound/waveform.py break.wav break.json docs/sound/break-waveform.svg

Two panels: the whole shot, and its first 0.35 s. Each event is a tick above the waveform,
coloured by kind, at its time from the result JSON; the waveform is the channels' mean.
"""
import json
import struct
import sys
import wave

COLOURS = {"cue-strike": "#d62728", "ball-ball": "#1f77b4", "ball-cushion": "#2ca02c", "ball-pocket": "#9467bd"}
W, PANEL_H, MARGIN_L, MARGIN_R, GAP = 1100, 170, 60, 20, 60


def read_mono(path):
    with wave.open(path) as w:
        rate, channels, frames = w.getframerate(), w.getnchannels(), w.getnframes()
        raw = w.readframes(frames)
    samples = struct.unpack("<%dh" % (frames * channels), raw)
    mono = [sum(samples[i * channels:(i + 1) * channels]) / (channels * 32768.0) for i in range(frames)]
    return rate, mono


def panel(out, top, title, rate, mono, events, t0, t1):
    width = W - MARGIN_L - MARGIN_R
    mid = top + PANEL_H / 2
    scale = PANEL_H / 2 * 0.95
    out.append(f'<text x="{MARGIN_L}" y="{top - 8}" font-size="13">{title}</text>')
    out.append(f'<rect x="{MARGIN_L}" y="{top}" width="{width}" height="{PANEL_H}" fill="none" stroke="#999"/>')
    first, last = int(t0 * rate), min(len(mono), int(t1 * rate))
    per = max(1, (last - first) // width)
    path = []
    for px in range(width):
        a = first + px * (last - first) // width
        chunk = mono[a:a + per] or [0]
        lo, hi = min(chunk), max(chunk)
        x = MARGIN_L + px
        path.append(f"M{x},{mid - hi * scale:.1f}V{mid - lo * scale + 0.5:.1f}")
    out.append(f'<path d="{"".join(path)}" stroke="#444" stroke-width="1"/>')
    for e in events:
        if t0 <= e["t"] <= t1:
            x = MARGIN_L + (e["t"] - t0) / (t1 - t0) * width
            out.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{top + 14}" stroke="{COLOURS.get(e["type"], "#000")}" stroke-width="1.5"/>')
    step = 0.05 if t1 - t0 < 1 else 0.5
    k = 0
    while k * step <= t1 - t0 + 1e-9:
        t = t0 + k * step
        x = MARGIN_L + (t - t0) / (t1 - t0) * width
        out.append(f'<text x="{x:.1f}" y="{top + PANEL_H + 14}" font-size="11" text-anchor="middle">{t:.2f}</text>')
        k += 1
    out.append(f'<text x="{MARGIN_L - 8}" y="{top + 10}" font-size="11" text-anchor="end">+1</text>')
    out.append(f'<text x="{MARGIN_L - 8}" y="{top + PANEL_H}" font-size="11" text-anchor="end">-1</text>')


def main():
    wav, result, svg = sys.argv[1:4]
    rate, mono = read_mono(wav)
    events = json.load(open(result))["events"]
    duration = len(mono) / rate
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{2 * PANEL_H + GAP + 90}" font-family="sans-serif">',
           f'<rect width="100%" height="100%" fill="white"/>']
    panel(out, 30, f"{wav}: the whole shot (s), {len(events)} events", rate, mono, events, 0, duration)
    panel(out, 30 + PANEL_H + GAP, "the first 0.35 s (s)", rate, mono, events, 0, 0.35)
    y = 2 * PANEL_H + GAP + 75
    x = MARGIN_L
    for name, colour in COLOURS.items():
        out.append(f'<line x1="{x}" y1="{y - 4}" x2="{x + 18}" y2="{y - 4}" stroke="{colour}" stroke-width="3"/>')
        out.append(f'<text x="{x + 24}" y="{y}" font-size="12">{name}</text>')
        x += 150
    out.append("</svg>")
    with open(svg, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
