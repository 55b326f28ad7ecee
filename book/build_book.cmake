# Builds the book: run as `cmake -DVIBOOK=... -DSOURCE_DIR=... -DBINARY_DIR=... -DDOXYGEN=...
# -P book/build_book.cmake` (the `book` target does this). Every number and figure in the
# book is regenerated here by the `vibook` command: nothing is typed in by hand.
cmake_minimum_required(VERSION 3.25)

if(NOT DOXYGEN)
  message(FATAL_ERROR "doxygen not found: install the Debian package doxygen (./build.sh book does)")
endif()
set(MATHJAX_SRC /usr/share/javascript/mathjax)
if(NOT EXISTS ${MATHJAX_SRC}/MathJax.js)
  message(FATAL_ERROR "MathJax 2 not found in ${MATHJAX_SRC}: install libjs-mathjax and fonts-mathjax")
endif()

set(OUT ${BINARY_DIR}/book)
set(GEN ${OUT}/gen)
set(IMAGES ${OUT}/images)
set(FIGS ${OUT}/figures)
file(REMOVE_RECURSE ${OUT}/html ${GEN} ${IMAGES} ${FIGS} ${OUT}/errata)
file(MAKE_DIRECTORY ${GEN} ${IMAGES} ${FIGS})

# 1. Figures: CSV, SVG, PNG and claims.json per figure, regenerated in parallel.
execute_process(COMMAND ${VIBOOK} figures --out ${FIGS} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "vibook figures failed (exit ${rc})")
endif()
file(GLOB images ${FIGS}/*/*.svg ${FIGS}/*/*-worldline.png)
file(COPY ${images} DESTINATION ${IMAGES})
# Long studies run only when VIBOOK_LONG_STUDIES is set (./build.sh book). Otherwise their
# image is a notice saying so, never a stand-in plot.
if(NOT EXISTS ${IMAGES}/bench-work-precision.svg)
  file(WRITE ${IMAGES}/bench-work-precision.svg
"<svg xmlns='http://www.w3.org/2000/svg' width='900' height='80'><rect width='900' height='80' fill='#f6f6f6' stroke='#999'/><text x='20' y='45' font-family='DejaVu Sans' font-size='16'>Benchmarks not run in this build: ./build.sh book (or ./build.sh bench) measures them.</text></svg>\n")
endif()
foreach(study sharma-eq29-long)
  if(NOT EXISTS ${IMAGES}/${study}.svg)
    file(WRITE ${IMAGES}/${study}.svg
"<svg xmlns='http://www.w3.org/2000/svg' width='900' height='80'><rect width='900' height='80' fill='#f6f6f6' stroke='#999'/><text x='20' y='45' font-family='DejaVu Sans' font-size='16'>Long study '${study}' not run in this build: ./build.sh book runs it (VIBOOK_LONG_STUDIES=1).</text></svg>\n")
  endif()
endforeach()

# 2. Claims: the ledger written as JSON and HTML tables. The figures' results (long studies
#    included) are read back from step 1's claims.json files, not measured twice; the checks
#    without a figure run now.
#    The provenance names the source commit: its hash and date (the commit's, not the build's,
#    so that two builds of one commit write the same bytes), and whether the tree differed.
find_program(GIT git)
set(commit "unknown (not a git checkout)")
if(GIT)
  execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} log -1 --format=%h%x20of%x20%cs
                  OUTPUT_VARIABLE git_commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET
                  RESULT_VARIABLE git_rc)
  if(git_rc EQUAL 0 AND git_commit)
    execute_process(COMMAND ${GIT} -C ${SOURCE_DIR} status --porcelain --untracked-files=no
                    OUTPUT_VARIABLE git_dirty OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    set(commit "${git_commit}")
    if(git_dirty)
      string(APPEND commit " with local changes")
    endif()
  endif()
endif()
execute_process(COMMAND ${VIBOOK} claims --json-out ${OUT}/claims.json --html-dir ${GEN}
                        --figures-dir ${FIGS} --commit ${commit}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "vibook claims failed (exit ${rc})")
endif()

find_program(PYTHON3 python3 REQUIRED)
# 2a. Every printed formula: one row per display the papers' text holds (`vibook displays`),
#     each outcome read from the comparisons of this ledger.
execute_process(COMMAND ${VIBOOK} displays --inline --json-out ${OUT}/displays.json
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "vibook displays failed (exit ${rc})")
endif()
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/formulas.py ${OUT}/claims.json
                        ${OUT}/displays.json ${GEN}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "formulas.py failed (exit ${rc})")
endif()

# 2a'. The errata sheets, one per paper (book/errata-*.md include them), and the same sheets as
#      Markdown, copied beside the HTML in step 4.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/errata.py ${OUT}/claims.json
                        ${OUT}/displays.json ${SOURCE_DIR}/papers ${GEN} ${OUT}/errata
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "errata.py failed (exit ${rc})")
endif()

# 2b. The modified-equations chapter's formulas, derived by the engine now.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/engine_formulas.py ${VIBOOK} ${GEN}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "engine_formulas.py failed (exit ${rc})")
endif()

# 2c. The example of the chapter "Verify your own integrator", run now: its output is quoted.
execute_process(COMMAND ${EXAMPLE} OUTPUT_FILE ${GEN}/verify-example.txt RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "examples/henon_heiles_simpson failed (exit ${rc}); see ${GEN}/verify-example.txt")
endif()

# Run in the figures directory, so that the quoted output names the report as a reader would
# type it, not by a path into this build tree.
execute_process(COMMAND ${VIBOOK} verify
                        --ld "h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)"
                        --potential "x^2/2+y^2/2+x^2*y-y^3/3" --q0 0,0.1 --p0 0.35,0
                        --report verify-report
                WORKING_DIRECTORY ${FIGS}
                OUTPUT_FILE ${GEN}/verify-cli.txt RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "vibook verify failed (exit ${rc}); see ${GEN}/verify-cli.txt")
endif()
file(COPY ${FIGS}/verify-report/verify-report.svg DESTINATION ${IMAGES})
# Three more for the chapter: a wrong discrete Lagrangian (the kinetic term doubled), which must
# fail with status 5; symplectic Euler, first order, with its modified Hamiltonian; a
# fourth-order method whose --h-list reaches the round-off plateau.
# Each writes its report (OUT), its JSON (OUT.json) and its standard error (OUT.stderr) to the
# generated directory: tests/cli/book_examples.sh checks the report lines, the verdict and the
# one-line message of the examples the CLI suites would otherwise run a second time.
function(vibook_verify_case out want)
  string(REGEX REPLACE "\\.txt$" "" stem ${out})
  execute_process(COMMAND ${VIBOOK} verify ${ARGN} --json-out ${GEN}/${stem}.json
                  OUTPUT_FILE ${GEN}/${out} ERROR_FILE ${GEN}/${stem}.stderr RESULT_VARIABLE rc)
  if(NOT rc EQUAL want)
    file(READ ${GEN}/${stem}.stderr err)
    message(FATAL_ERROR "vibook verify (${out}) exited ${rc}, expected ${want}: ${err}")
  endif()
endfunction()
vibook_verify_case(verify-wrong-kinetic.txt 5
                   --ld "h*((q1-q0)^2/h^2 - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)"
                   --potential "x^2/2+y^2/2+x^2*y-y^3/3" --q0 0,0.1 --p0 0.35,0
                   --modified-order 0)
vibook_verify_case(verify-euler.txt 0
                   --ld "h*( ((q1-q0)/h)^2/2 - V(q1) )" "--potential=-cos(x)" --q0 1 --p0 0.5
                   --expected-order 1 --modified-order 1)
vibook_verify_case(verify-order4.txt 0
                   --ld "h*( ((q1-q0)/h)^2/2*(1 + h^2/12*(cos(q0[1])+cos(q1[1]))) - (V(q0)+V(q1))/2 - h^2/48*(grad(V)(q0)^2 + grad(V)(q1)^2) )"
                   "--potential=-cos(x)" --q0 1 --p0 0.5 --expected-order 4 --modified-order 2)
# The typed method as an energy-preserving adaptive integrator (section "Beyond Sharma"):
# Simpson on Hénon–Heiles passes; EpAVI itself (the midpoint rule) on a Kepler orbit of
# eccentricity 0.8 has no admissible step.
vibook_verify_case(verify-adaptive.txt 0
                   --ld "h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)"
                   --potential "x^2/2+y^2/2+x^2*y-y^3/3" --q0 0,0.1 --p0 0.35,0
                   --modified-order 0 --adaptive epavi)
vibook_verify_case(verify-adaptive-kepler.txt 5
                   --ld "h*(((q1-q0)/h)^2/2 - V((q0+q1)/2))" "--potential=-1/sqrt(x^2+y^2)"
                   --q0 0.2,0 --p0 0,3 --h 0.001 --t-end 1 --h-list 0.01,0.005,0.0025,0.00125
                   --modified-order 0 --adaptive epavi)

# Compositions (the chapter's section "Compositions"): a catalogue method that must pass and two
# deliberately wrong ones that must fail with status 5. The audit of every catalogue composition
# is a check of the ledger (field-audit, step 2), not a run here.
vibook_verify_case(verify-composition-yoshida6.txt 0 --composition sv --coefficients yoshida6)
vibook_verify_case(verify-composition-perturbed.txt 5 --composition sv --coefficients
                   "0.784513610477560,0.235573213359357,-1.17767998416887,1.315186320663906,-1.17767998416887,0.235573213359357,0.784513610477560"
                   --expected-order 6)
vibook_verify_case(verify-composition-swapped.txt 5 --composition se --coefficients
                   "3/8,7/24*,-25/24,3/8*,0,1*" --expected-order 3)
# Splittings (the chapter's section "Splittings"): Forest-Ruth must pass; the same flows with the
# last half drift moved to the front must fail (order 1).
vibook_verify_case(verify-splitting-forest-ruth.txt 0 --splitting forest-ruth --problem kepler)
vibook_verify_case(verify-splitting-moved.txt 5 --splitting
                   "drift:1/(2-2^(1/3)),kick:1/(2-2^(1/3)),drift:(1-2^(1/3))/(2*(2-2^(1/3))),kick:-2^(1/3)/(2-2^(1/3)),drift:(1-2^(1/3))/(2*(2-2^(1/3))),kick:1/(2-2^(1/3))"
                   --problem pendulum --expected-order 4)
# A Runge-Kutta-Nystrom splitting: order 3 for two generic flows, 4 by its Nystrom trees.
vibook_verify_case(verify-splitting-mclachlan-atela.txt 0 --splitting mclachlan-atela-4
                   --problem pendulum)

# A method from its tableau (the chapter's section "A method from its tableau"), run in
# examples/tableaus so that the report names the file as a reader would type it: Lobatto
# IIIA-IIIB must pass, Lobatto IIIA for both halves must fail (not symplectic).
function(vibook_verify_tableau out want file)
  execute_process(COMMAND ${VIBOOK} verify --tableau ${file} ${ARGN} OUTPUT_FILE ${GEN}/${out}
                  WORKING_DIRECTORY ${SOURCE_DIR}/examples/tableaus
                  ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL want)
    message(FATAL_ERROR "vibook verify (${out}) exited ${rc}, expected ${want}: ${err}")
  endif()
endfunction()
vibook_verify_tableau(verify-tableau-lobatto3.txt 0 lobatto3-iiia-iiib.json)
vibook_verify_tableau(verify-tableau-iiia.txt 5 wrong-lobatto3-iiia-only.json)
vibook_verify_tableau(verify-tableau-hamiltonian.txt 0 lobatto3-iiia-iiib.json --hamiltonian
                      "p^2/(2*(1+q^2)) + q^2/2 + q^4/4" --q0 0.5 --p0 0.3)
# The frontier (chapter, "The criteria of every route"): Lobatto IIIA with four stages must fail
# symplecticity by the growth of its defect; Gauss with six stages must pass at order 12, its
# order study in double-double.
vibook_verify_tableau(verify-tableau-lobatto4.txt 5 wrong-lobatto4-iiia-only.json --problem pendulum)
vibook_verify_tableau(verify-tableau-gauss6.txt 0 gauss6.json --problem kepler)
# Runge-Kutta-Nystrom tableaus (the chapter's section "Runge-Kutta-Nystrom tableaus"): Gauss 3
# as an RKN passes at order 6; HNW's explicit fifth-order method reaches order 5 and fails the
# symplecticity verdict; its three-coefficient corruption is order 2.
vibook_verify_tableau(verify-tableau-rkn-gauss3.txt 0 gauss3-rkn.json --problem henon-heiles)
vibook_verify_tableau(verify-tableau-rkn5.txt 5 rkn5-hnw.json --problem kepler)
vibook_verify_tableau(verify-tableau-rkn5-three.txt 5 wrong-rkn5-three.json --problem kepler)
vibook_verify_tableau(verify-tableau-rkn-mclachlan5.txt 0 mclachlan-atela-5-rkn.json
                      --problem henon-heiles)

# Galerkin variational integrators (the chapter's section "Galerkin variational integrators").
vibook_verify_case(verify-method-lobatto3.txt 0 --method lobatto:3 --problem kepler)
vibook_verify_case(verify-method-typed.txt 0 --method lobatto:3 --potential x^2/2+y^2/2+x^2*y-y^3/3
                   --q0 0.1,0.2 --p0 0.3,0.1)
vibook_verify_case(verify-method-lagrangian.txt 0 --method gauss:2 --lagrangian
                   "sqrt(1+q[2]^2)*v[1]^2/2 + v[2]^2/(2*sqrt(1+q[2]^2)) - q[1]^2/2 - q[2]^4/4"
                   --q0 0.3,0.5 --p0 0.2,-0.1)
# Time-dependent systems (the chapter's section "Time-dependent systems"): Gauss 2 on a forced
# oscillator must pass; the midpoint L_d with the forcing at the step's start time must fail
# (order 1); a Python Stormer-Verlet over line protocol 2 on a forced pendulum must pass.
vibook_verify_case(verify-time-gauss2.txt 0 --method gauss:2 --lagrangian "v^2/2 - q^2/2 + q*cos(t)"
                   --q0 0.5 --p0 0 --expected-order 4)
vibook_verify_case(verify-time-ld-stale.txt 5 --ld
                   "h*(((q1-q0)/h)^2/2 + cos((q0+q1)/2) + (q0+q1)/2*cos(t)/2)"
                   "--potential=-cos(x) - x*cos(t)/2" --q0 0.5 --p0 0 --symmetric)
vibook_verify_case(verify-time-python.txt 0 --stepper-cmd
                   "python3 ${SOURCE_DIR}/examples/black_box/forced_stepper.py sv forced-pendulum"
                   --stepper-protocol 2 --hamiltonian "p^2/2 - cos(q) - q*cos(t)/2" --q0 0.5 --p0 0
                   --expected-order 2 --symmetric)
# Constrained systems (the chapter's section "Constrained systems"): RATTLE on the spherical
# pendulum must pass; without its velocity projection it must fail (the hidden constraint).
vibook_verify_case(verify-rattle.txt 0 --method rattle --problem spherical-pendulum)
vibook_verify_case(verify-shake.txt 5 --method shake --problem spherical-pendulum)
# The triple jump composed of RATTLE steps (the chapter's "Compositions of RATTLE").
vibook_verify_case(verify-rattle-yoshida4.txt 0 --composition rattle --coefficients yoshida4
                   --problem spherical-pendulum)
# Constraints typed after --constraint: RATTLE on the double pendulum typed as V and two
# constraints must pass; the constrained discrete Euler-Lagrange equations of the trapezoidal
# L_d must pass at order 2 (RATTLE written variationally), those of V at q1 alone must fail there.
vibook_verify_case(verify-constraint-double.txt 0 --method rattle --potential "q[2]+q[4]"
                   --constraint "(q[1]^2+q[2]^2-1)/2"
                   --constraint "((q[3]-q[1])^2+(q[4]-q[2])^2-1)/2"
                   --q0=0.479425538604203,-0.8775825618903728,1.3208965234120995,-1.4178848677585125
                   --p0=0,0,0.2701511529340699,0.42073549240394825)
vibook_verify_case(verify-constraint-ld.txt 0 --ld "h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)"
                   --potential z --constraint "(x^2+y^2+z^2-1)/2"
                   --q0 0.8414709848078965,0,-0.5403023058681398 --p0 0,0.8,0 --symmetric)
vibook_verify_case(verify-constraint-python.txt 0 --stepper-cmd
                   "python3 ${SOURCE_DIR}/examples/black_box/rattle_stepper.py rattle"
                   --potential z --constraint "(x^2+y^2+z^2-1)/2"
                   --q0 0.8414709848078965,0,-0.5403023058681398 --p0 0,0.8,0
                   --expected-order 2 --symmetric)
vibook_verify_case(verify-constraint-ld-v1.txt 5 --ld "h*((q1-q0)^2/(2*h^2) - V(q1))"
                   --potential z --constraint "(x^2+y^2+z^2-1)/2"
                   --q0 0.8414709848078965,0,-0.5403023058681398 --p0 0,0.8,0)
# Every Galerkin method on Kepler and Henon-Heiles is the long study field-audit-galerkin (rows
# A-GAUSS1 ... A-LOBATTO5 of the ledger), measured in step 2 when VIBOOK_LONG_STUDIES is set.

# Black boxes (the chapter's section "Any stepper as a black box"): Boost.Odeint's fourth-order
# McLachlan stepper through the C ABI, which must pass; odeint's velocity Verlet called without
# reset, which must fail; a Python composition with its pairs swapped, which must fail.
vibook_verify_case(verify-stepper-odeint.txt 0 --stepper-lib ${STEPPER_LIB}
                   --stepper-arg mclachlan4/kepler --problem kepler --expected-order 4)
vibook_verify_case(verify-stepper-cached.txt 5 --stepper-lib ${STEPPER_LIB}
                   --stepper-arg velocity_verlet_cached/kepler --expected-order 2 --symmetric)
vibook_verify_case(verify-stepper-rk78.txt 5 --stepper-lib ${STEPPER_LIB}
                   --stepper-arg rk78/kepler --expected-order 8 --order-tol 0.5)
vibook_verify_case(verify-stepper-python.txt 5 --stepper-cmd
                   "python3 ${SOURCE_DIR}/examples/black_box/stepper.py ruth3_swapped pendulum"
                   --problem pendulum --expected-order 3 --steps 4096)
foreach(f verify-stepper-odeint.txt verify-stepper-cached.txt verify-stepper-rk78.txt
          verify-stepper-python.txt verify-time-python.txt verify-constraint-python.txt)
  # the build tree's and the source tree's paths are not the reader's
  file(READ ${GEN}/${f} text)
  string(REPLACE "${STEPPER_LIB}" "vibook_odeint_steppers.so" text "${text}")
  string(REPLACE "${SOURCE_DIR}/" "" text "${text}")
  file(WRITE ${GEN}/${f} "${text}")
endforeach()

# 3. Benchmarks: the table of the last `./build.sh bench` run, or of a run made now when
#    VIBOOK_BOOK_BENCH is set (./build.sh book sets it; the test build does not).
set(BENCH_JSON ${BINARY_DIR}/bench/bench.json)
set(BENCH_EXE ${BINARY_DIR}/tests/bench/vibook_bench)
if(DEFINED ENV{VIBOOK_BOOK_BENCH} AND NOT EXISTS ${BENCH_EXE})
  message(FATAL_ERROR "VIBOOK_BOOK_BENCH is set but ${BENCH_EXE} is not built (./build.sh book "
                      "builds it: cmake --build build --target vibook_bench)")
endif()
if(DEFINED ENV{VIBOOK_BOOK_BENCH} AND EXISTS ${BENCH_EXE})
  file(MAKE_DIRECTORY ${BINARY_DIR}/bench)
  message(STATUS "Running the benchmarks for the book (about four minutes)")
  execute_process(COMMAND ${BENCH_EXE} --benchmark_out=${BENCH_JSON} --benchmark_out_format=json
                          --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
                  OUTPUT_QUIET RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "vibook_bench failed (exit ${rc})")
  endif()
  message(STATUS "Timing SymPy on the engine's cost table (tests/bench/sympy_lmod.py)")
  execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/tests/bench/sympy_lmod.py
                          --table ${BINARY_DIR}/bench/sympy.txt --timeout 120
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sympy_lmod.py --table failed (exit ${rc})")
  endif()
endif()
if(EXISTS ${BENCH_JSON})
  set(SYMPY_ARGS)
  if(EXISTS ${BINARY_DIR}/bench/sympy.txt)
    set(SYMPY_ARGS --sympy ${BINARY_DIR}/bench/sympy.txt)
  endif()
  execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/tests/bench/bench_table.py ${SYMPY_ARGS}
                          ${BENCH_JSON} ${BINARY_DIR}/bench/work_precision.csv
                          ${GEN}/bench-adaptive.html
                  OUTPUT_FILE ${GEN}/bench.html RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "bench_table.py failed")
  endif()
  if(EXISTS ${BINARY_DIR}/bench/work_precision.csv)
    execute_process(COMMAND gnuplot -c ${SOURCE_DIR}/figures/bench-work-precision.gp
                            ${BINARY_DIR}/bench/work_precision.csv ${IMAGES}/bench-work-precision
                    RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "gnuplot failed on bench-work-precision.gp")
    endif()
  endif()
else()
  file(WRITE ${GEN}/bench.html
       "<p><em>Not measured in this build.</em> Run <code>./build.sh bench</code> (or "
       "<code>./build.sh book</code>, which runs the benchmarks) to fill this table.</p>\n")
  file(COPY_FILE ${GEN}/bench.html ${GEN}/bench-adaptive.html)
endif()

# 3b. The chapters' prose quotes measured values as [[CLAIM:value]]: each must be in this
#     ledger (Doxygen's input filter, book/ledger_text.py, substitutes them).
file(GLOB chapters ${SOURCE_DIR}/book/*.md)
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/ledger_text.py --check ${OUT}/claims.json
                        ${chapters}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ledger_text.py: a chapter quotes a value the ledger does not have")
endif()

# 4. Doxygen, then MathJax next to the HTML so that the book works offline.
file(READ ${SOURCE_DIR}/CMakeLists.txt top)
string(REGEX MATCH "project\\(vibook VERSION ([0-9.]+)" _ "${top}")
set(ENV{VIBOOK_VERSION} "${CMAKE_MATCH_1}")
set(ENV{VIBOOK_SOURCE_DIR} ${SOURCE_DIR})
set(ENV{VIBOOK_BOOK_OUT} ${OUT})
set(ENV{VIBOOK_BOOK_GEN} ${GEN})
set(ENV{VIBOOK_BOOK_IMAGES} ${IMAGES})
execute_process(COMMAND ${DOXYGEN} ${SOURCE_DIR}/Doxyfile WORKING_DIRECTORY ${SOURCE_DIR}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit ${rc})")
endif()
file(COPY ${MATHJAX_SRC}/ DESTINATION ${OUT}/html/mathjax
     PATTERN "unpacked" EXCLUDE
     PATTERN "test" EXCLUDE
     REGEX "mathjax/fonts(/.*)?$" EXCLUDE)  # HTML-CSS web fonts: not used by SVG output
file(COPY ${FIGS} DESTINATION ${OUT}/html)  # CSV and PNG beside the book, for download
file(COPY ${OUT}/claims.json DESTINATION ${OUT}/html)  # the whole ledger, linked from the index
file(GLOB errata_md ${OUT}/errata/errata-*.md)
file(COPY ${errata_md} DESTINATION ${OUT}/html)  # the errata sheets as text, linked from each
# Every chapter figure numbered, a link to its full-size picture, its caption listing its CSVs.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/figure_links.py ${OUT}/html ${SOURCE_DIR}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "figure_links.py failed (exit ${rc})")
endif()
# Previous/next links in the order of the table of contents.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/chapter_nav.py ${OUT}/html ${SOURCE_DIR}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "chapter_nav.py failed (exit ${rc})")
endif()
# The first page's map of the papers (figures, statements, equations -> the book) and the
# search entries for claim IDs, equation numbers and figures.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/paper_map.py ${OUT}/html ${SOURCE_DIR}
                        ${OUT}/claims.json ${OUT}/displays.json
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "paper_map.py failed (exit ${rc})")
endif()
# The report's evidence: chapter and figure, CSV data and the check's source for every claim.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/report_evidence.py ${OUT}/html ${SOURCE_DIR}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "report_evidence.py failed (exit ${rc})")
endif()
# A partial build says so on every page that shows something it did not measure.
execute_process(COMMAND ${PYTHON3} ${SOURCE_DIR}/book/partial_notice.py ${OUT}/html
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "partial_notice.py failed (exit ${rc})")
endif()
if(EXISTS ${OUT}/doxygen-warnings.log)
  file(READ ${OUT}/doxygen-warnings.log warnings)
  if(NOT warnings STREQUAL "")
    # A warning is a broken \ref, a \snippet whose marker is gone, a formula Doxygen could not
    # parse: the book would show it broken, so the build fails.
    message(FATAL_ERROR "Doxygen warnings (${OUT}/doxygen-warnings.log):\n${warnings}")
  endif()
endif()
