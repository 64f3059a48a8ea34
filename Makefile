# budge: `make test` checks everything CI checks; `make bench` measures.
.PHONY: test lint spec bench bench-world

test:
	@sh tools/test.sh

lint:
	luacheck .

spec:
	busted

# World bench: LuaJIT at full size, Lua 5.4 with fewer frames (it is ~10x slower).
bench-world:
	luajit bench/world.lua --runs 3
	lua5.4 bench/world.lua --runs 3 --frames 60
	luajit bench/platforms.lua --runs 5
	lua5.4 bench/platforms.lua --runs 3 --frames 100

# Speed against accuracy: the scenario catalogue and the world bench scene for every
# method on LuaJIT and Lua 5.4 (median of 5 runs), then the charts in docs/.
bench:
	@sh tools/deps.sh luajit lua5.4
	@mkdir -p bench/results docs
	luajit bench/run.lua --runs 5
	lua5.4 bench/run.lua --runs 5
	lua5.4 bench/chart.lua
