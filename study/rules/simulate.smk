# One run: configure -> simulate -> measure, in results/<sweep>/<point>/ (logs in its logs/).

localrules: configure

if "SLIDEWAVE_BIN" not in os.environ:
    SOLVER_SOURCES = sorted(str(p.relative_to(REPO)) for p in (REPO / "solver").rglob("*") if p.is_file())

    rule build_solver:
        """Build the solver CLI (Release) when a source is newer than the binary."""
        input:
            "CMakeLists.txt",
            "cmake/git_version.cmake",
            SOLVER_SOURCES,
        output: "build/slidewave"
        log: "logs/build_solver.log"
        threads: 2
        shell:
            "(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release"
            " && cmake --build build --target slidewave -j{threads:q}) > {log:q} 2>&1"


rule configure:
    """Write the solver configuration of one point (study/make_run_config.py)."""
    output: "results/{sweep}/{point}/config.json"
    params: spec=lambda wc: json.dumps(run_spec(wc.sweep, wc.point), sort_keys=True)
    log: "results/{sweep}/{point}/logs/configure.log"
    shell: "{PYTHON:q} -m study.make_run_config --spec {params.spec:q} -o {output:q} 2> {log:q}"


rule simulate:
    """`slidewave run`: stages 1-3 of one point, interface fields and global series in run.h5."""
    input:
        config="results/{sweep}/{point}/config.json",
        solver=SOLVER,
    output: "results/{sweep}/{point}/run.h5"
    log: "results/{sweep}/{point}/logs/simulate.log"
    benchmark: "results/{sweep}/{point}/logs/simulate.benchmark.tsv"
    threads: 1
    resources:
        mem_mb=lambda wc: run_estimate(wc.sweep, wc.point)["mem_mb"],
        runtime=lambda wc: run_estimate(wc.sweep, wc.point)["runtime"],
    # Exit codes of `slidewave run` (docs/contracts.md): 0 complete; 1 contact failure, run.h5 written
    # with complete = 0 (a physical outcome: kept and measured as what it is, so that one hard point
    # cannot stop a sweep). Anything else fails the job and leaves no output: 2 bad input, 3 interrupted
    # (only RUN.partial.h5 and the checkpoint beside run.h5, which the next attempt resumes from),
    # 4 I/O error, a crash. An interrupted run is therefore never an output of this rule; the trap keeps
    # it so also when the job itself is signalled (Snakemake stopped, a scheduler's time limit).
    shell: "trap \"rm -f {output:q}; exit 143\" TERM INT; status=0; {input.solver:q} run {input.config:q} -o {output:q} --threads {threads:q} --resume"
           " > {log:q} 2>&1 || status=$?;"
           " [ $status -eq 0 ] || {{ [ $status -eq 1 ] && [ -f {output:q} ]; }}"
           " || {{ echo \"simulate: slidewave run exited $status: no result\" >> {log:q}; rm -f {output:q}; exit 1; }}"


rule measure:
    """`python3 -m analysis measure`: onset, celerity, opening, inversion, category of one run."""
    input: "results/{sweep}/{point}/run.h5"
    output: "results/{sweep}/{point}/metrics.json"
    log: "results/{sweep}/{point}/logs/measure.log"
    resources: mem_mb=2000, runtime=10
    shell: "{PYTHON:q} -m analysis measure {input:q} -o {output:q} > {log:q} 2>&1"
