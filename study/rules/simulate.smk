# One run: simulate (its config.json and `slidewave run`) -> measure, in results/runs/<point>-<digest>/
# (logs in its logs/), shared by every sweep that declares the same run (study/rules/common.smk).

from study import in_process

localrules: measure

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
        # First: every run waits for it. Without a priority, `all` started the 2-minute contrast theory on one
        # of the two cores and the build (which takes both) waited for it: 1.7 of 17.9 min.
        priority: 100
        shell:
            "(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release"
            " && cmake --build build --target slidewave -j{threads:q}) > {log:q} 2>&1"


rule simulate:
    """One run in its folder results/runs/<point>-<digest> (study/rules/common.smk): its config.json
    (the resolved configuration, study/make_run_config.py, passed from the Snakefile so that no
    process starts for it), then `slidewave run`: stages 1-3, interface fields and global series in
    run.h5."""
    input: solver=SOLVER
    output:
        config="results/runs/{run}/config.json",
        run="results/runs/{run}/run.h5",
    params: config=lambda wc: run_config_text(*run_owner(wc.run))
    log: "results/runs/{run}/logs/simulate.log"
    benchmark: "results/runs/{run}/logs/simulate.benchmark.tsv"
    threads: 1
    resources:
        mem_mb=lambda wc: run_estimate(*run_owner(wc.run))["mem_mb"],
        runtime=lambda wc: run_estimate(*run_owner(wc.run))["runtime"],
    # Exit codes of `slidewave run` (docs/contracts.md): 0 complete; 1 contact failure, run.h5 written
    # with complete = 0 (a physical outcome: kept and measured as what it is, so that one hard point
    # cannot stop a sweep). Anything else fails the job and leaves no output: 2 bad input, 3 interrupted
    # (only RUN.partial.h5 and the checkpoint beside run.h5, which the next attempt resumes from),
    # 4 I/O error, a crash. An interrupted run is therefore never an output of this rule; the trap keeps
    # it so also when the job itself is signalled (Snakemake stopped, a scheduler's time limit).
    shell: "trap \"rm -f {output.run:q}; exit 143\" TERM INT; printf %s {params.config:q} > {output.config:q};"
           " status=0; {input.solver:q} run {output.config:q} -o {output.run:q} --threads {threads:q} --resume"
           " > {log:q} 2>&1 || status=$?;"
           " [ $status -eq 0 ] || {{ [ $status -eq 1 ] && [ -f {output.run:q} ]; }}"
           " || {{ echo \"simulate: slidewave run exited $status: no result\" >> {log:q}; rm -f {output.run:q}; exit 1; }}"


rule measure:
    """`python3 -m analysis measure` (onset, celerity, opening, inversion, category of one run), run by
    the Snakemake process itself (study/in_process.py): no Python start-up per run."""
    input: "results/runs/{run}/run.h5"
    output: "results/runs/{run}/metrics.json"
    log: "results/runs/{run}/logs/measure.log"
    # A thread of the Snakemake process, whose own work no core of --cores is kept for either: the next
    # run starts on the core the finished one freed while this one is measured.
    threads: 0
    run: in_process.measure(input[0], output[0], log[0])
