# The two commands of the README. Both install missing Debian packages, configure and build.
#   make demo   render a tetrahedral mesh to a PNG and print what was done
#   make test   run the whole test suite under ctest
#   make paraview  fetch ParaView privately (5.11 on Debian 12, 5.13 on Debian 13), build the
#                  ParaView plugin, say how to load it
# The three detect the release (Module/debian-release.sh): Debian 12 or 13, else a message.
# Developer targets:
#   make build      configure and build ./build only
#   make sanitize   build ./build-asan with ASan and UBSan and run the tests under them
#   make test-debian13  build and test the same sources (the whole suite, ParaView 5.13's plugin
#                   included) against Debian 13's VTK 9.3, in a Debian 13 root made and cached
#                   under build/debian13 (root, network); ARGS=--bundle: its GPU bundle
#   make install PREFIX=...
.PHONY: demo test build sanitize install clean paraview test-debian13

build:
	Module/build.sh

demo:
	Module/demo.sh $(ARGS)

test:
	Module/test.sh

# Never installs ParaView (it would remove VTK's development package): docs/paraview.md.
paraview:
	ParaView/build-plugin.sh

# make sanitize ARGS="-R Python" runs only some tests (ARGS go to ctest, through the shell: quote a
# pattern with | in it, ARGS="-R 'BadInput|Scenes'").
sanitize:
	Module/sanitize.sh $(ARGS)

# make test-debian13 ARGS="-R Scenes" runs only some tests (ARGS go to ctest).
test-debian13:
	Module/test-debian13.sh $(ARGS)

# make install PREFIX=/some/where
PREFIX ?= /usr/local
install: build
	cmake --install build --prefix "$(PREFIX)"

clean:
	rm -rf build build-asan
