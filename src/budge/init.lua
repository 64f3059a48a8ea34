-- budge: good-enough AABB collision for LÖVE and any Lua 5.1-5.4 / LuaJIT host.
-- This file only re-exports; each function lives in the module named beside it.
-- README.md in this folder lists the modules in the order they depend on each other:
-- box, resolve, fatcross, sweep, hash, tilegrid, layer, hits, actors, solids, entry,
-- move, carry, query, contacts, world, tiles, advise; each requires only modules before it.
--
-- MIT License. Copyright (c) 2026 the budge developers. See LICENSE in the
-- distribution; the notice travels with this folder when it is copied into a game.

local here = (...):gsub("%.init$", "")
local box = require(here .. ".box")
local resolve = require(here .. ".resolve")
local fatcross = require(here .. ".fatcross")
local move = require(here .. ".move")
local world = require(here .. ".world")
local tiles = require(here .. ".tiles")
local advise = require(here .. ".advise")

local budge = {
  _VERSION = "0.1.0",
  _DESCRIPTION = "Good-enough AABB collision for LÖVE: detect, resolve, measure",
  _URL = "https://github.com/budge-lua/budge",
  _LICENSE = "MIT",
}

budge.detect_collision = box.detect_collision     -- box.lua
budge.resolve_collision = resolve.resolve_collision -- resolve.lua
budge.fat_cross = fatcross.fat_cross              -- fatcross.lua
budge.resolve_fat_cross = fatcross.resolve_fat_cross
budge.new_world = world.new_world                -- world.lua
budge.tiles = {merge = tiles.merge}              -- tiles.lua
budge.advise = advise.advise                     -- advise.lua
-- world:move's method names, cheapest rung of the ladder first (a copy: move.lua's
-- registry is the one place they are written), and the set of those that never tunnel
budge.METHODS, budge.CONTINUOUS = {}, {}
for i, name in ipairs(move.LADDER) do
  budge.METHODS[i] = name
  budge.CONTINUOUS[name] = move.BY_NAME[name].continuous or nil
end

return budge
