#!/usr/bin/python3
"""The columns of a bushing run's time_history.csv that doc/verification/bushing.md
draws and quotes, into a small CSV kept beside the figures, so that a later
run can be compared with a default-mesh run whose output directory is gone
(a 40 ms run at n = 2 takes hours; its full history has 355 columns):

    /usr/bin/python3 doc/scripts/bushing_history_columns.py IN.csv OUT.csv

Keeps time, the energy balance, the issue's five columns, the weight's
contact force and velocity, and each contact pair's energy error; rows as
in the input. doc/scripts/bushing_histories.py reads the result.
"""
import csv
import sys

KEPT = ["time", "time_step", "kinetic_energy", "internal_energy",
        "external_work", "contact_work", "friction_work", "added_mass",
        "energy_error", "energy_error_deformable", "drop_weight_force",
        "bolt_axial_force", "bolt_bending_moment", "inner_sleeve_slip",
        "outer_sleeve_pull_out", "weight_plate_normal_force",
        "drop_weight_velocity_z", "bolt_section_force"]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        reader = csv.DictReader(f)
        missing = [k for k in KEPT if k not in reader.fieldnames]
        if missing:
            sys.exit(sys.argv[1] + ": no column " + ", ".join(missing))
        pairs = [k for k in reader.fieldnames
                 if k.endswith("_energy_error") and k not in KEPT]
        columns = KEPT + pairs
        # (A run still writing may have an incomplete last row.)
        rows = [row for row in reader
                if None not in row.values() and "" not in row.values()]
    with open(sys.argv[2], "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            writer.writerow(row[k] for k in columns)


if __name__ == "__main__":
    main()
