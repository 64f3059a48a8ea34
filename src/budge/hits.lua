-- budge.hits: the contact records of one move. The world owns an array of them, reused
-- from move to move (no garbage once warm); a move fills them from index 1 and sorts
-- them into the order they happened.

local hits = {}

---One contact of a move. Owned by the world and reused: valid until the next move.
---@class budge.Hit
---@field other table the solid box, or the tile layer handle
---@field side "floor"|"ceiling"|"left"|"right" which side of the actor touched
---@field col? integer the tile's column, for a tile layer
---@field row? integer the tile's row, for a tile layer
---@field package _top number sort keys: the top and left of what was met,
---@field package _left number
---@field package _id integer the order its item was added,
---@field package _round integer and the phase of the move it happened in

---Appends a contact with `other` (a solid box, or a tile layer with the tile's col and
---row) to the world's hits, in the world's current round; `top` and `left` are the
---corner of what was met (the box's, or the tile's), its sort keys.
---LuaJIT shaping: the callers pass top and left, which they have at hand; computed here
---from `other`, the branch made make bench-jit's platformer compile 606 traces and
---790-813 KB instead of 535 and 621-627 (median of 6 runs with a budget that never runs
---out, 2026-12-01).
---@param world budge.World
---@param other table
---@param side "floor"|"ceiling"|"left"|"right"
---@param col? integer
---@param row? integer
---@param top number
---@param left number
---@param id integer
function hits.add(world, other, side, col, row, top, left, id)
  local n = world._n_hits + 1
  local hit = world._hits[n]
  if hit == nil then
    hit = {}
    world._hits[n] = hit
  end
  hit.other, hit.side, hit.col, hit.row = other, side, col, row
  hit._top, hit._left = top, left
  hit._id, hit._round = id, world._round
  world._n_hits = n
end

-- Contacts of one move come out in the order they happened (x before y), and within one
-- round by position (top, then left) and then by the order items were added.
local function hit_before(a, b)
  if a._round ~= b._round then return a._round < b._round end
  if a._top ~= b._top then return a._top < b._top end
  if a._left ~= b._left then return a._left < b._left end
  return a._id < b._id
end

---Sorts the world's hits 1.._n_hits into the order they happened.
---Speed: an insertion sort, not table.sort: a move has a handful of contacts, and
---table.sort's calls back into Lua leave LuaJIT's compiled code. With table.sort the
---world bench's tile moves take 304 ns instead of 232 on LuaJIT, 2454 instead of 2290 on
---Lua 5.4 (`luajit bench/world.lua --profile tiles`, median of 5, 2026-12-01).
---@param world budge.World
function hits.sort(world)
  local list = world._hits
  for i = 2, world._n_hits do
    local hit = list[i]
    local j = i - 1
    while j >= 1 and hit_before(hit, list[j]) do
      list[j + 1] = list[j]
      j = j - 1
    end
    list[j + 1] = hit
  end
end

return hits
