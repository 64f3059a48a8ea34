# budge: `make test` checks everything CI checks; `make bench` measures.
.PHONY: test lint spec

test:
	@sh tools/test.sh

lint:
	luacheck .

spec:
	busted
