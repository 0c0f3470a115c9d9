# Animations (`snakemake -c2 movies`): for each entry of `movies.runs`, one run with bulk snapshots
# every `frame_transits` H/c_s in its time range, and its movie (figures/movie.py), all in
# results/movies/<name>/. The runs are separate from the sweeps' (they write ~0.3 MB per frame at
# H/64), so a movie never makes a sweep's run.h5 heavy.

import shutil

localrules: movie_configure

# MP4 through ffmpeg; a GIF when ffmpeg is missing (figures/movie.py says so in the log).
MOVIE_EXT = ".mp4" if shutil.which("ffmpeg") else ".gif"

wildcard_constraints:
    movie="(?!nu)[a-z][a-z0-9_]*",


def movie_entry(name):
    return config["movies"]["runs"][name]


def movie_spec(name):
    """The run specification (study/make_run_config.py) of one movie: its point over the defaults,
    snapshots every frame_transits from start_transits to end_transits after the onset estimate, and
    interface output every step so that the profiles are those of the frame's step."""
    entry = movie_entry(name)
    start, end, stride = entry["start_transits"], entry["end_transits"], entry["frame_transits"]
    n_frames = int(round((end - start) / stride)) + 1
    return {
        "point": {**config["defaults"], **entry["point"]},
        "model": config["model"],
        "run_length": {**config["run_length"], **entry.get("run_length", {})},
        "solver": _deep_merge(config["solver"], {"output": {"interface_stride": 1}}),
        "snapshot_offsets_transits": [round(start + k * stride, 9) for k in range(n_frames)],
    }


def movie_files():
    return [f"results/movies/{name}/movie{MOVIE_EXT}" for name in config["movies"]["runs"]]


rule movie_configure:
    """The solver configuration of one movie run (study/make_run_config.py)."""
    output: "results/movies/{movie}/config.json"
    params: spec=lambda wc: json.dumps(movie_spec(wc.movie), sort_keys=True)
    log: "results/movies/{movie}/logs/configure.log"
    shell: "{PYTHON:q} -m study.make_run_config --spec {params.spec:q} -o {output:q} 2> {log:q}"


rule movie_simulate:
    """`slidewave run` of one movie run (exit 1 with a written file: kept, as in `simulate`)."""
    input:
        config="results/movies/{movie}/config.json",
        solver=SOLVER,
    output: "results/movies/{movie}/run.h5"
    log: "results/movies/{movie}/logs/simulate.log"
    benchmark: "results/movies/{movie}/logs/simulate.benchmark.tsv"
    threads: 1
    shell: "status=0; {input.solver:q} run {input.config:q} -o {output:q} --threads {threads:q} > {log:q} 2>&1 || status=$?;"
           " [ $status -eq 0 ] || {{ [ $status -eq 1 ] && [ -f {output:q} ]; }}"


rule movie_render:
    """figures/movie.py: the frames of one movie run, encoded at `movies.frame_rate`."""
    input:
        script=figure_script("movie"),
        helpers=figure_script("_movie_frames"),
        run="results/movies/{movie}/run.h5",
    output: "results/movies/{movie}/movie" + MOVIE_EXT
    params: fps=lambda wc: config["movies"]["frame_rate"]
    log: "results/movies/{movie}/logs/render.log"
    benchmark: "results/movies/{movie}/logs/render.benchmark.tsv"
    shell: "{PYTHON:q} {input.script:q} {input.run:q} --fps {params.fps:q} --out {output:q} > {log:q} 2>&1"
