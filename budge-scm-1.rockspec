rockspec_format = "3.0"
package = "budge"
version = "scm-1"
source = {
  url = "git+https://github.com/budge-lua/budge.git",
}
description = {
  summary = "Good-enough AABB collision for LÖVE: detect, resolve, measure",
  detailed = [[
budge detects and resolves collisions between axis-aligned boxes that never rotate.
It starts from the "wall_type" and "fat cross" methods of a well-known blog article and
offers a ladder of methods up to exact continuous sweeping, each measured for speed and
accuracy and pinned in specs where it fails.]],
  homepage = "https://github.com/budge-lua/budge",
  license = "MIT",
  labels = {"love", "love2d", "collision", "aabb", "gamedev"},
}
dependencies = {
  "lua >= 5.1",
}
test_dependencies = {
  "busted",
}
build = {
  type = "builtin",
  modules = {
    ["budge"] = "src/budge/init.lua",
    ["budge.box"] = "src/budge/box.lua",
    ["budge.resolve"] = "src/budge/resolve.lua",
    ["budge.fatcross"] = "src/budge/fatcross.lua",
    ["budge.sweep"] = "src/budge/sweep.lua",
    ["budge.hash"] = "src/budge/hash.lua",
    ["budge.tilegrid"] = "src/budge/tilegrid.lua",
    ["budge.layer"] = "src/budge/layer.lua",
    ["budge.hits"] = "src/budge/hits.lua",
    ["budge.actors"] = "src/budge/actors.lua",
    ["budge.solids"] = "src/budge/solids.lua",
    ["budge.entry"] = "src/budge/entry.lua",
    ["budge.move"] = "src/budge/move.lua",
    ["budge.carry"] = "src/budge/carry.lua",
    ["budge.query"] = "src/budge/query.lua",
    ["budge.contacts"] = "src/budge/contacts.lua",
    ["budge.world"] = "src/budge/world.lua",
    ["budge.tiles"] = "src/budge/tiles.lua",
    ["budge.advise"] = "src/budge/advise.lua",
    ["budge.bump"] = "src/budge/bump.lua",
  },
}
test = {
  type = "busted",
}
