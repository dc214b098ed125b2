# femgear: `make demo` and `make test` work on a fresh clone (they create .venv).
PY      ?= python3
VENV    := .venv
BIN     := $(VENV)/bin
STAMP   := $(VENV)/.installed
OUT     ?= out
# small dense matrices (24-DOF dynamics): threaded BLAS only adds overhead on 2 cores
export OPENBLAS_NUM_THREADS ?= 1
export OMP_NUM_THREADS ?= 1

.PHONY: demo test test-slow bench docs gallery validation clean sysdeps cholmod

$(STAMP): pyproject.toml
	@$(MAKE) --no-print-directory sysdeps
	$(PY) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q -e '.[test,docs]'
	@$(MAKE) --no-print-directory cholmod
	@touch $(STAMP)

# System libraries, installed when missing (root + apt only): gmsh's shared library needs a few X/GL
# libraries; SuiteSparse (CHOLMOD, METIS) and OpenBLAS for scikit-sparse (target cholmod); EGL with Mesa's
# software renderer for the gallery's off-screen pyvista pictures (docs/gen/render.py; no display needed).
SYSPKG := libglu1-mesa libxcursor1 libxft2 libxinerama1 libgl1 libsuitesparse-dev libopenblas0-pthread \
          libegl1 libegl-mesa0 libgl1-mesa-dri
sysdeps:
	@if command -v apt-get >/dev/null 2>&1 && [ "$$(id -u)" = 0 ] && \
		{ ! ldconfig -p | grep -q libGLU.so.1 || [ ! -f /usr/include/suitesparse/cholmod.h ] || \
		  ! ldconfig -p | grep -q libEGL_mesa.so.0; }; then \
		echo "installing system libraries (gmsh, SuiteSparse, OpenBLAS, EGL)"; \
		apt-get update -qq && apt-get install -y -qq $(SYSPKG) >/dev/null; \
	fi

# The 3-D body factors through the system's CHOLMOD (scikit-sparse 0.4, built against the SuiteSparse 5-6
# headers; its 0.5 for SuiteSparse 7 has another API, not used yet): 10-20x faster than the cholespy wheel,
# which stays the fallback (femgear.physics.body.elastic3d, docs/cost.md).  A failed build only costs speed.
cholmod:
	@v=$$(sed -n 's/^#define SUITESPARSE_MAIN_VERSION *\([0-9]*\).*/\1/p' /usr/include/suitesparse/SuiteSparse_config.h 2>/dev/null); \
	if [ -z "$$v" ]; then echo "femgear: no SuiteSparse headers: the 3-D bodies use the cholespy wheel (slower, docs/cost.md)"; \
	elif [ "$$v" -ge 7 ]; then echo "femgear: SuiteSparse $$v: scikit-sparse 0.4 needs 5-6; the 3-D bodies use the cholespy wheel (slower, docs/cost.md)"; \
	else spec='scikit-sparse>=0.4.12,<0.5'; \
		echo "building $$spec against SuiteSparse $$v (log: $(VENV)/cholmod-build.log)"; \
		$(BIN)/pip install "$$spec" > $(VENV)/cholmod-build.log 2>&1 || \
			echo "femgear: scikit-sparse did not build ($(VENV)/cholmod-build.log): the 3-D bodies use the cholespy wheel (slower, docs/cost.md)"; \
	fi

demo: $(STAMP)
	$(BIN)/femgear run studies/paper_baseline.toml --out $(OUT)/paper_baseline

# pytest workers (pytest-xdist): CI's two cores; more where there are cores and memory (~1 GB a worker)
TEST_WORKERS ?= 2

test: $(STAMP)
	$(BIN)/ruff check femgear tests studies meshes docs/gen docs/examples
	$(BIN)/mkdocs build --strict --quiet --site-dir $(OUT)/site
	$(BIN)/python -m pytest -q -n $(TEST_WORKERS)

test-slow: $(STAMP)
	$(BIN)/python -m pytest -q -m slow

# the docs site (mkdocs.yml): warnings are errors; open $(OUT)/site/index.html.  First the gallery's stale
# figures are remade (docs/gen/gallery.py: none when its inputs did not change, a few seconds to check;
# each stale command 5-50 s, all of them about 4.5 minutes on 2 shared cores); `make gallery` remakes every figure
# (also those whose physics moved under an unchanged digest: the digest sees scenes, commands and drawing code).
docs: $(STAMP)
	@$(BIN)/python docs/gen/gallery.py || echo "docs: some gallery figures could not be remade (above): the site shows the committed ones"
	$(BIN)/mkdocs build --strict --site-dir $(OUT)/site
	@echo "docs: $(OUT)/site/index.html"

gallery: $(STAMP)
	$(BIN)/python docs/gen/gallery.py --all

# every table of the docs' validation pages, regenerated from the studies (long: well over half an hour on 2 cores;
# outputs and figures in $(OUT)/<study>/; docs/validation/speed-accuracy.md is rewritten, the zoo table written to $(OUT)/zoo_matrix/table.md)
VALIDATION := studies/dynamics/eccentricity.py studies/paper/wear_cycles.py studies/paper/temperature_rise.py studies/paper/dynamic_backlash.py \
              studies/paper/meshing_error.py studies/paper/mixed_friction.py studies/ltca/ltca_claims.py studies/validation/iso6336_checks.py \
              studies/body/ross_pem.py studies/dynamics/spur_jump.py studies/dynamics/overlap_load.py
validation: $(STAMP)
	@for s in $(VALIDATION); do echo "== $$s"; $(BIN)/python $$s || exit 1; done
	$(BIN)/python studies/paper/rig_conditions.py --ltca
	$(BIN)/python studies/validation/speed_accuracy.py --readme
	$(BIN)/python studies/validation/zoo_matrix.py --jobs 2 --coarse --markdown $(OUT)/zoo_matrix/table.md
	@echo "validation: tables printed above; docs/validation/speed-accuracy.md rewritten; the zoo table (for docs/zoo_matrix.md) in $(OUT)/zoo_matrix/table.md"

bench: $(STAMP)
	@for f in studies/benchmarks/*.py; do echo "== $$f"; $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(OUT) .pytest_cache .ruff_cache build *.egg-info
