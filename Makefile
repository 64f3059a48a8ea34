# budge: `make test` checks everything CI checks; `make bench` measures.
.PHONY: test lint spec bench bench-world bench-jit bench-game demo game screenshots

test:
	@sh tools/test.sh

lint:
	luacheck .

spec:
	busted

# World bench: LuaJIT at full size, Lua 5.4 with fewer frames (it is ~10x slower); each
# writes its table into the README (between its markers), with bump.lua beside it when found.
bench-world:
	BUMP_PATH=$${BUMP_PATH:-../shared/peers/bump.lua-3.1.7} luajit bench/world.lua --runs 5 --readme README.md
	BUMP_PATH=$${BUMP_PATH:-../shared/peers/bump.lua-3.1.7} lua5.4 bench/world.lua --runs 5 --frames 60 --readme README.md
	luajit bench/platforms.lua --runs 5
	lua5.4 bench/platforms.lua --runs 3 --frames 100
	BUMP_PATH=$${BUMP_PATH:-../shared/peers/bump.lua-3.1.7} luajit bench/contacts.lua --runs 5 --readme README.md
	BUMP_PATH=$${BUMP_PATH:-../shared/peers/bump.lua-3.1.7} luajit bench/contacts.lua --runs 5 --budget large --readme README.md
	BUMP_PATH=$${BUMP_PATH:-../shared/peers/bump.lua-3.1.7} lua5.4 bench/contacts.lua --runs 5 --frames 60 --readme README.md

# Speed against accuracy: the scenario catalogue and the world bench scene for every
# method on LuaJIT and Lua 5.4 (median of 5 runs), then the charts in docs/.
bench:
	@sh tools/deps.sh luajit lua5.4
	@mkdir -p bench/results docs
	luajit bench/run.lua --runs 5
	lua5.4 bench/run.lua --runs 5
	lua5.4 bench/chart.lua

# The LÖVE lab. Installs LÖVE when missing; without a display it says how to run the
# scripted mode instead.
demo:
	@sh tools/deps.sh love
	@if [ -z "$${DISPLAY:-}$${WAYLAND_DISPLAY:-}" ]; then \
	  echo "no display here: the lab needs a window. Its scripted mode runs anywhere:"; \
	  echo "  xvfb-run -a -s '-screen 0 1024x768x24' love examples/demo --scene speed --method seed --frames 240 --screenshot lab.png"; \
	  echo "(make test runs every scene that way)"; \
	else love examples/demo; fi

# The README's pictures of the lab, from its scripted mode.
screenshots:
	@sh tools/deps.sh love xvfb-run
	timeout 60 xvfb-run -a -s "-screen 0 1024x768x24" love examples/demo --scene speed --method seed --frames 240 --screenshot docs/demo.png
	timeout 60 xvfb-run -a -s "-screen 0 1024x768x24" love examples/demo --scene fatcross --method fat_cross --frames 100 --screenshot docs/demo-fatcross.png
	timeout 60 xvfb-run -a -s "-screen 0 1024x768x24" love examples/demo --scene platformer --method fat_cross --frames 300 --screenshot docs/demo-platformer.png
	# (mid-level, so its verdict is not the play-through's: the picture is what is wanted)
	-timeout 60 xvfb-run -a -s "-screen 0 1024x768x24" love examples/platformer --script playthrough --frames 420 --screenshot docs/platformer.png

# The example platformer as the measure of speed in a game: its play-through for 5000
# frames headless, on LuaJIT three ways (default budget, raised budget, JIT off) and on
# Lua 5.4.
bench-game:
	@sh tools/deps.sh luajit lua5.4
	luajit bench/game.lua --frames 5000 --runs 5 --readme examples/platformer/README.md
	lua5.4 bench/game.lua --frames 5000 --runs 5 --readme examples/platformer/README.md

# The example platformer under LÖVE (examples/platformer). Without a display it says how
# to run its scripted mode instead.
game:
	@sh tools/deps.sh love
	@if [ -z "$${DISPLAY:-}$${WAYLAND_DISPLAY:-}" ]; then \
	  echo "no display here: the game needs a window. Its scripted mode runs anywhere:"; \
	  echo "  xvfb-run -a -s '-screen 0 1024x768x24' love examples/platformer --script playthrough --screenshot game.png"; \
	  echo "  luajit examples/platformer/headless.lua --script playthrough"; \
	else love examples/platformer; fi

# How much machine code budge makes LuaJIT compile, against its default budget.
bench-jit:
	@sh tools/deps.sh luajit
	luajit bench/jit.lua --frames 3000 --runs 5 --why 8 --readme README.md
