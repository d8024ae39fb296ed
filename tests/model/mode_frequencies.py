#!/usr/bin/env python3
"""The strongest vibration frequencies of a history column.

Usage: mode_frequencies.py CSV COLUMN [COLUMN2] START FMIN FMAX N

The column (or COLUMN - COLUMN2, e.g. the stretch between a bar's two ends)
from time START on, resampled at even steps (linear interpolation between
rows), its mean removed, under a Hann window; the N largest peaks of its
discrete Fourier transform between FMIN and FMAX (1/ms), each refined by a
parabola through the amplitudes of its neighbours on an 8-times finer
frequency grid. Prints 'frequency amplitude' per peak, in increasing
frequency. Standard library only.
"""
import csv
import math
import sys


def column(path, name, other):
    times, values = [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            times.append(float(row['time']))
            value = float(row[name])
            if other:
                value -= float(row[other])
            values.append(value)
    return times, values


def resample(times, values, start, step):
    out, k = [], 0
    x = start
    while x <= times[-1]:
        while times[k + 1] < x:
            k += 1
        w = (x - times[k]) / (times[k + 1] - times[k])
        out.append(values[k] * (1 - w) + values[k + 1] * w)
        x += step
    return out


def peaks(samples, step, fmin, fmax, count):
    n = len(samples)
    mean = sum(samples) / n
    windowed = [(v - mean) * (0.5 - 0.5 * math.cos(2 * math.pi * i / (n - 1)))
                for i, v in enumerate(samples)]

    def amplitude(f):
        c = s = 0.0
        for i, v in enumerate(windowed):
            a = 2 * math.pi * f * i * step
            c += v * math.cos(a)
            s += v * math.sin(a)
        return math.hypot(c, s)

    df = 1 / (n * step) / 8
    grid = [fmin + i * df for i in range(int((fmax - fmin) / df))]
    amplitudes = [amplitude(f) for f in grid]
    found = [i for i in range(1, len(grid) - 1)
             if amplitudes[i] > amplitudes[i - 1]
             and amplitudes[i] >= amplitudes[i + 1]]
    found.sort(key=lambda i: -amplitudes[i])
    result = []
    for i in found[:count]:
        a, b, c = amplitudes[i - 1], amplitudes[i], amplitudes[i + 1]
        shift = 0.5 * (a - c) / (a - 2 * b + c)
        result.append((grid[i] + shift * df, b))
    return sorted(result)


def main():
    args = sys.argv[1:]
    if len(args) == 7:
        path, name, other, start, fmin, fmax, count = args
    else:
        path, name, start, fmin, fmax, count = args
        other = None
    times, values = column(path, name, other)
    fmax = float(fmax)
    # At least 8 samples per period of the highest frequency looked at.
    step = 1 / (8 * fmax)
    samples = resample(times, values, float(start), step)
    for f, a in peaks(samples, step, float(fmin), fmax, int(count)):
        print('%.6g %.6g' % (f, a))


main()
