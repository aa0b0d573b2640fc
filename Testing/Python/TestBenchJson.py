"""`lfd bench --quick --threads 2 --json FILE`: every table's rows with their
figures (ms/frame, rays/s, the ratio to the reference loop at the same frame
size and thread count, the same time and ratio in process CPU time, the
run-queue wait, the threads, peak memory), the lookup rows again on one
thread, memory against the light field's raw bytes, the machine's cores and
load average; the schema and the consistency of the figures, not their
values (timings are not tested)."""
import json
import os
import shutil

import lfdtesting as t

WORK = t.temp_path("TestBenchJson", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
path = os.path.join(WORK, "bench.json")
code, out, err = t.run_lfd("bench", "--quick", "--threads", "2", "--json", path)
t.check(code == 0 and os.path.isfile(path), "lfd bench --quick --threads 2 --json",
        err.strip() or out[-300:])
bench = json.load(open(path))
t.check((bench["format"], bench["version"], bench["quick"], bench["repeat"], bench["sizes"])
        == ("lfd-bench", 1, True, 1, [64, 128]), "the run's settings",
        {k: bench[k] for k in ("format", "version", "quick", "repeat", "sizes")})
machine = bench["machine"]
t.check(machine["cores"] == os.cpu_count() and machine["threads"] == 2
        and machine["smp_backend"] and all(len(machine[k]) == 3 and min(machine[k]) >= 0
                                            for k in ("load_average_start", "load_average_end")),
        "the machine: cores, threads, load average", machine)
t.check(bench["peak_rss_scope"] == "configuration", "each configuration's own peak memory",
        bench["peak_rss_scope"])
startup = bench["startup_rss_bytes"]

rows = bench["rows"]
tables = {}
for row in rows:
    tables.setdefault(row["table"], []).append(row)
# 2 sizes: the reference loop, 2 objects x (undeformed, deformed), on 2
# threads and again on one; at 128 (the largest size): the fish on its proxy
# (undeformed, deformed), 2 light-field sizes, 2 cages, the two-plane fish (4
# nearest, aperture), the fish out of core (caches of 1/4, 1/2 and 1x its bytes).
t.check({k: len(v) for k, v in tables.items()}
        == {"reference": 2, "render": 8, "one thread": 10, "proxy": 2, "light-field size": 2,
            "cage size": 2, "two-plane": 2, "out of core": 3},
        "the rows of each table", {k: len(v) for k, v in tables.items()})
common = {"table", "name", "size", "pixels", "views", "image_size", "light_field_bytes", "boxes",
          "threads", "ms_per_frame", "rays_per_second", "vs_reference", "cpu_ms_per_frame",
          "cpu_vs_reference", "wait_ms_per_frame", "start_rss_bytes", "peak_rss_bytes"}
# Every ratio to another row comes twice: on the wall clock and in CPU time ("cpu_").
extra = {"reference": set(), "light-field size": {"rss_vs_raw", "render_mb", "render_vs_raw"},
         "cage size": {"vs_3_boxes", "cpu_vs_3_boxes", "no_accel_ms", "no_accel_cpu_ms"},
         "proxy": {"vs_plane", "cpu_vs_plane"}, "two-plane": set(),
         "out of core": {"vs_in_memory", "cpu_vs_in_memory", "cache_mb", "tiles_read",
                         "identical"}}
for row in rows:
    keys = set(row) - common
    wanted = extra.get(row["table"], {"vs_rest", "cpu_vs_rest"} if row["boxes"] else set())
    if row["table"] == "one thread":
        wanted = wanted | {"vs_threads", "cpu_vs_threads"}
    if row["table"] in ("render", "one thread") and not row["name"].startswith("reference loop"):
        # The reference loop timed in turn with the object's two renders.
        wanted = wanted | {"vs_ref_in_turn", "cpu_vs_ref_in_turn"}
    t.check(common <= set(row) and keys == wanted, f"the fields of {row['table']}: {row['name']}",
            sorted(row))
# Each row ran on the threads asked for: the one-thread table on 1, every other on 2.
t.check([r["threads"] for r in rows] == [1 if r["table"] == "one thread" else 2 for r in rows],
        "the threads of each row", [(r["table"], r["threads"]) for r in rows])
# The ratios to the reference loop are to the loop at the same size on as many threads.
reference = {(r["size"], r["threads"]): r for r in rows if r["name"].startswith("reference loop")}
t.check(sorted(reference) == [(64, 1), (64, 2), (128, 1), (128, 2)],
        "the reference loop at each size on 2 threads and on one", sorted(reference))
schedstat = os.path.exists("/proc/thread-self/schedstat")
for row in rows:
    ms, cpu, pixels = row["ms_per_frame"], row["cpu_ms_per_frame"], row["pixels"]
    floor = reference[(row["size"], row["threads"])]
    wait = row["wait_ms_per_frame"]
    consistent = (ms > 0 and cpu > 0 and pixels == row["size"] ** 2
                  and abs(row["rays_per_second"] * ms / 1000 - pixels) < 1e-6 * pixels
                  and abs(row["vs_reference"] - ms / floor["ms_per_frame"]) < 1e-9 * ms
                  and abs(row["cpu_vs_reference"] - cpu / floor["cpu_ms_per_frame"]) < 1e-9 * cpu
                  # the calling thread's wait lies within the frame's wall time
                  and (0 <= wait <= ms if schedstat else wait is None)
                  and row["peak_rss_bytes"] >= row["start_rss_bytes"] > startup > 0
                  and row["peak_rss_bytes"] > row["light_field_bytes"] > 0)
    t.check(consistent,
            f"{row['table']}: {row['name']} at {row['size']}: rays/s, ratios, CPU time, wait, "
            "memory", row)
# One thread against the same rows on 2 threads: the ratios of their times.
for row in tables["one thread"]:
    same = [r for r in tables["reference"] + tables["render"]
            if (r["name"], r["size"]) == (row["name"], row["size"])]
    t.check(len(same) == 1
            and abs(row["vs_threads"] - row["ms_per_frame"] / same[0]["ms_per_frame"]) < 1e-9
            * row["vs_threads"]
            and abs(row["cpu_vs_threads"] - row["cpu_ms_per_frame"] / same[0]["cpu_ms_per_frame"])
            < 1e-9 * row["cpu_vs_threads"] and row["vs_threads"] > 0,
            f"one thread: {row['name']} at {row['size']}: against 2 threads", row)
# The ratio to the loop timed in turn: the same loop for the undeformed and deformed row
# of an object (their ratio is vs_rest's, up to the medians' rounding).
for table in ("render", "one thread"):
    for row in tables[table]:
        if row["name"].startswith("reference loop"):
            continue
        t.check(row["vs_ref_in_turn"] > 0 and row["cpu_vs_ref_in_turn"] > 0,
                f"{table}: {row['name']}: the ratios to the loop timed in turn", row)
    for rest, deformed in zip(tables[table][0::2], tables[table][1::2]):
        if rest["name"].startswith("reference loop") or "vs_rest" not in deformed:
            continue
        t.check(abs(deformed["vs_ref_in_turn"] / rest["vs_ref_in_turn"] - deformed["vs_rest"])
                < 1e-9 * deformed["vs_rest"],
                f"{table}: {deformed['name']}: in turn with its undeformed row and the loop",
                (rest, deformed))
# Memory against the light field's raw bytes: the process's peak, the render's increment.
for row in tables["light-field size"]:
    raw, peak, start = row["light_field_bytes"], row["peak_rss_bytes"], row["start_rss_bytes"]
    t.check(abs(row["rss_vs_raw"] - peak / raw) < 1e-9 * peak / raw
            and abs(row["render_mb"] - (peak - start) / 1048576) < 1e-9 * peak
            and abs(row["render_vs_raw"] - (peak - start) / raw) < 1e-9 * peak,
            f"light-field size: {row['name']}: memory against raw bytes", row)
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
for table in ("reference loop", "one thread (like for like", "light-field size", "cage size",
              "focal surface: proxy", "two-plane fish", "out of core"):
    t.check(table in out, f"the printed table '{table}'", out[:200])
t.check("cpu ms" in out and "cpu/ref" in out and "wait ms" in out,
        "the printed CPU and wait columns", out[:400])
t.check(f"start-up floor: {startup / 1048576:.0f} MB resident" in out,
        "the printed start-up floor", out[:300])
t.finish()
