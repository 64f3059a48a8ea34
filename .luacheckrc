-- src/ runs on Lua 5.1-5.4 and LuaJIT, so it may use only what all of them share.
std = "min"
max_line_length = 120
exclude_files = {"lua_modules/", ".luarocks/", "tmp/"}

files["spec/"] = {std = "+busted"}
files["examples/"] = {std = "luajit+love"}
files["bench/"] = {std = "min"}
-- a Tiled export keeps its rows of tile ids on one line each, as Tiled writes them
files["examples/platformer/level.lua"] = {max_line_length = false}
