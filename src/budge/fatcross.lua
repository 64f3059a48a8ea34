-- budge.fatcross: the seed article's "fat cross". A solid block is replaced by two
-- overlapping hitboxes: a tall one (typed "horizontal": it pushes up or down) inset from
-- the block's left and right faces, and a wide one (typed "vertical": it pushes left or
-- right) inset from its top and bottom faces.
--
-- Why the inset equals the speed: a mover that moves at most `max_speed` per step and
-- hits the block's left face penetrates it by at most `max_speed`; the tall box starts
-- `inset` inside that face, and touching is not a collision, so the mover meets only the
-- wide box exactly while its speed <= inset. The same holds for the other three faces.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local resolve = require(here .. ".resolve")

local overlaps = box.overlaps
local check_box, describe = box.check_box, box.describe
local by_wall_type = resolve.RULES.wall_type
local format, error, is_finite = string.format, error, box.is_finite

local fatcross = {}

---The largest per-step speed a block of this size can serve is just under half its
---smaller side: above that, the tall or the wide hitbox would have no thickness left.
---@param width number
---@param height number
---@return number limit speeds must stay strictly below this
function fatcross.speed_limit(width, height)
  return (width < height and width or height) / 2
end

---Returns the two hitboxes of `block`'s fat cross, sized for movers that move at most
---`max_speed` px per step on each axis: `tall` (wall_type "horizontal", inset on x by
---`max_speed`) and `wide` (wall_type "vertical", inset on y by `max_speed`).
---Both are new tables; `block` is not changed.
---@param block budge.Box
---@param max_speed number > 0 and < half the block's smaller side
---@return budge.Box tall, budge.Box wide
function fatcross.fat_cross(block, max_speed)
  check_box(block, "box", 2)
  if not is_finite(max_speed) or max_speed <= 0 then
    error(format("max_speed must be a finite number > 0, got %s", describe(max_speed)), 2)
  end
  local limit = fatcross.speed_limit(block.width, block.height)
  if max_speed >= limit then
    error(format("box is too small for max_speed %s: a %sx%s box serves speeds below %s "
      .. "(half its smaller side)", describe(max_speed), describe(block.width),
      describe(block.height), describe(limit)), 2)
  end
  local inset = max_speed
  local tall = {x = block.x + inset, y = block.y, width = block.width - 2 * inset,
    height = block.height, wall_type = "horizontal"}
  local wide = {x = block.x, y = block.y + inset, width = block.width,
    height = block.height - 2 * inset, wall_type = "vertical"}
  return tall, wide
end

---Resolves `mover` against one crossed block (unchecked; for inner loops).
---The tall box goes first: a mover that overlaps both was coming down (or up) faster
---than the inset, and pushing it vertically first lands it on top instead of throwing
---it off the side; the wide box is then tested again with the mover where it now is.
---@param mover budge.Box
---@param tall budge.Box
---@param wide budge.Box
---@return number dx, number dy
function fatcross.resolve_pair(mover, tall, wide)
  local dx, dy = 0, 0
  if overlaps(mover, tall) then
    dx, dy = by_wall_type(mover, tall)
  end
  if overlaps(mover, wide) then
    local wide_dx, wide_dy = by_wall_type(mover, wide)
    dx, dy = dx + wide_dx, dy + wide_dy
  end
  return dx, dy
end

---Resolves `mover` against one block's fat cross (the two boxes `budge.fat_cross`
---returned) and returns the push it applied, dx, dy.
---@param mover budge.Box
---@param tall budge.Box wall_type "horizontal"
---@param wide budge.Box wall_type "vertical"
---@return number dx, number dy
function fatcross.resolve_fat_cross(mover, tall, wide)
  check_box(mover, "mover", 2)
  check_box(tall, "tall", 2)
  check_box(wide, "wide", 2)
  if tall.wall_type ~= "horizontal" then
    error(format('tall.wall_type must be "horizontal" (the first box budge.fat_cross '
      .. "returns), got %s", describe(tall.wall_type)), 2)
  end
  if wide.wall_type ~= "vertical" then
    error(format('wide.wall_type must be "vertical" (the second box budge.fat_cross '
      .. "returns), got %s", describe(wide.wall_type)), 2)
  end
  return fatcross.resolve_pair(mover, tall, wide)
end

return fatcross
