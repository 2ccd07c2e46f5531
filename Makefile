# The two commands of the README. Both install missing Debian packages, configure and build.
#   make demo   render a tetrahedral mesh to a PNG and print what was done
#   make test   run the whole test suite under ctest
.PHONY: demo test build install clean

build:
	Module/build.sh

demo:
	Module/demo.sh $(ARGS)

test:
	Module/test.sh

# make install PREFIX=/some/where
PREFIX ?= /usr/local
install: build
	cmake --install build --prefix "$(PREFIX)"

clean:
	rm -rf build
