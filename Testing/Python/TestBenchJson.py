"""`lfd bench --quick --json FILE`: every table's rows with their figures
(ms/frame, rays/s, the ratio to the reference loop at the same frame size,
the same time and ratio in process CPU time, peak memory), the machine's cores and load average; the schema and the
consistency of the figures, not their values (timings are not tested)."""
import json
import os
import shutil

import lfdtesting as t

WORK = t.temp_path("TestBenchJson", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
path = os.path.join(WORK, "bench.json")
code, out, err = t.run_lfd("bench", "--quick", "--json", path)
t.check(code == 0 and os.path.isfile(path), "lfd bench --quick --json", err.strip() or out[-300:])
bench = json.load(open(path))
t.check((bench["format"], bench["version"], bench["quick"], bench["repeat"], bench["sizes"])
        == ("lfd-bench", 1, True, 1, [64, 128]), "the run's settings",
        {k: bench[k] for k in ("format", "version", "quick", "repeat", "sizes")})
machine = bench["machine"]
t.check(machine["cores"] == os.cpu_count() and machine["threads"] >= 1
        and machine["smp_backend"] and all(len(machine[k]) == 3 and min(machine[k]) >= 0
                                            for k in ("load_average_start", "load_average_end")),
        "the machine: cores, threads, load average", machine)
t.check(bench["peak_rss_scope"] == "configuration", "each configuration's own peak memory",
        bench["peak_rss_scope"])

rows = bench["rows"]
tables = {}
for row in rows:
    tables.setdefault(row["table"], []).append(row)
# 2 sizes: the reference loop, 2 objects x (undeformed, deformed); at 128
# (the largest size): the fish on its proxy (undeformed, deformed), 2
# light-field sizes, 2 cages, the two-plane fish (4 nearest, aperture), the
# fish out of core (caches of 1/4, 1/2 and 1x its bytes).
t.check({k: len(v) for k, v in tables.items()}
        == {"reference": 2, "render": 8, "proxy": 2, "light-field size": 2, "cage size": 2,
            "two-plane": 2, "out of core": 3},
        "the rows of each table", {k: len(v) for k, v in tables.items()})
common = {"table", "name", "size", "pixels", "views", "image_size", "light_field_bytes", "boxes",
          "ms_per_frame", "rays_per_second", "vs_reference", "cpu_ms_per_frame",
          "cpu_vs_reference", "peak_rss_bytes"}
# Every ratio to another row comes twice: on the wall clock and in CPU time ("cpu_").
extra = {"reference": set(), "light-field size": set(),
         "cage size": {"vs_3_boxes", "cpu_vs_3_boxes", "no_accel_ms", "no_accel_cpu_ms"},
         "proxy": {"vs_plane", "cpu_vs_plane"}, "two-plane": set(),
         "out of core": {"vs_in_memory", "cpu_vs_in_memory", "cache_mb", "tiles_read",
                         "identical"}}
for row in rows:
    keys = set(row) - common
    wanted = extra.get(row["table"], {"vs_rest", "cpu_vs_rest"} if row["boxes"] else set())
    t.check(common <= set(row) and keys == wanted, f"the fields of {row['table']}: {row['name']}",
            sorted(row))
reference = {r["size"]: r["ms_per_frame"] for r in tables["reference"]}
reference_cpu = {r["size"]: r["cpu_ms_per_frame"] for r in tables["reference"]}
for row in rows:
    ms, cpu, pixels = row["ms_per_frame"], row["cpu_ms_per_frame"], row["pixels"]
    consistent = (ms > 0 and cpu > 0 and pixels == row["size"] ** 2
                  and abs(row["rays_per_second"] * ms / 1000 - pixels) < 1e-6 * pixels
                  and abs(row["vs_reference"] - ms / reference[row["size"]]) < 1e-9 * ms
                  and abs(row["cpu_vs_reference"] - cpu / reference_cpu[row["size"]]) < 1e-9 * cpu
                  and row["peak_rss_bytes"] > row["light_field_bytes"] > 0)
    t.check(consistent,
            f"{row['table']}: {row['name']} at {row['size']}: rays/s, ratios, CPU time, memory",
            row)
# The proxy's cost against the plane, on the wall clock and in CPU time.
for row in tables["proxy"]:
    t.check(row["cpu_vs_plane"] > 0 and row["vs_plane"] > 0,
            f"proxy: {row['name']}: the ratios to the plane, wall and CPU", row)
t.check([r["views"] for r in tables["light-field size"]] == [12, 24]
        and [r["image_size"] for r in tables["light-field size"]] == [32, 64]
        and [r["light_field_bytes"] for r in tables["light-field size"]]
        == [12 * 32 * 32 * 4, 24 * 64 * 64 * 4],
        "light-field sizes: views, resolution and bytes (RGB + label)", tables["light-field size"])
t.check([r["boxes"] for r in tables["cage size"]] == [1, 3]
        and tables["cage size"][1]["vs_3_boxes"] == 1.0, "cage sizes 1 and 3", tables["cage size"])
t.check([r["identical"] for r in tables["out of core"]] == [1, 1, 1]
        and all(r["tiles_read"] > 0 for r in tables["out of core"]),
        "out of core: every frame equals the in-memory one, tiles were read", tables["out of core"])
for table in ("reference loop", "light-field size", "cage size", "focal surface: proxy",
              "two-plane fish", "out of core"):
    t.check(table in out, f"the printed table '{table}'", out[:200])
t.check("cpu ms" in out and "cpu/ref" in out, "the printed CPU columns", out[:400])
t.finish()
