-- budge.sweep: the continuous rungs of the ladder, solved over a candidate set.
--
-- A candidate set is a struct of parallel arrays (x, y, w, h, oneway, other, col, row,
-- id) filled by the broad phase, so that a move allocates nothing. Two solvers:
--
-- * stop_forward / stop_backward: where a box moving along one axis stops against one
--   candidate ("axis_sweep" applies them for x, then for y from where x ended: the
--   actors-and-solids model of the Celeste and TowerFall games, done with exact faces
--   instead of pixel by pixel; grid.lua runs them over tiles and hashed boxes).
-- * first_contact: the time of impact of a box moving along a straight diagonal
--   ("swept": the classic swept AABB of the Minkowski-sum literature), with each
--   contact classified by the axis it came in on.
--
-- Touching is not a collision: a face counts only when the mover's interval overlaps
-- the candidate's strictly on the other axis, so sliding along a floor made of separate
-- tiles never catches on a seam.

local HUGE = math.huge

local sweep = {}

sweep.NORMAL_X, sweep.NORMAL_Y, sweep.NORMAL_CORNER = 1, 2, 3

---A new, empty candidate set.
function sweep.new_set()
  return {
    n = 0, x = {}, y = {}, w = {}, h = {}, oneway = {}, other = {}, col = {}, row = {},
    id = {},
    touch = {}, normal = {}, touch_n = 0,
  }
end

---The largest position p with p + size <= face: where a box of `size` stops with its
---leading edge on `face`. Equal to face - size whenever that is exact (integers, and
---halves, quarters... of them); otherwise a few ulps less, never an overlap.
function sweep.before(face, size)
  local position = face - size
  if position + size > face then
    local step = ((face < 0 and -face or face) + size) * 2 ^ -52
    repeat position = position - step until position + size <= face
  end
  return position
end

-- The axis rules: where a box moving along one axis stops against one candidate.
-- `pos` and `edge` are the box's low and high coordinates on that axis, `reach` the
-- leading edge's coordinate after the full move. The caller has checked that the
-- candidate overlaps the box strictly on the other axis.
--
-- A candidate stops the box when its near face lies ahead within reach. A box the game
-- teleported into a candidate may leave it but not go deeper: a candidate whose near
-- face is inside the box stops it where it is, which keeps an actor squeezed between two
-- walls in place instead of passing it through one. Oneway candidates stop only moves
-- that `blocks_oneway` (down), and only from outside.

---Moving toward +x or +y against a candidate whose low face is at `near`: the position
---where the box stops, or nil.
function sweep.stop_forward(near, pos, edge, reach, size, oneway, blocks_oneway)
  if near <= pos or near >= reach then return nil end
  if near >= edge then
    if blocks_oneway or not oneway then return sweep.before(near, size) end
    return nil
  end
  if not oneway then return pos end
  return nil
end

---Moving toward -x or -y against a candidate whose high face is at `far`: the position
---where the box stops, or nil.
function sweep.stop_backward(far, pos, edge, reach, oneway, blocks_oneway)
  if far >= edge or far <= reach then return nil end
  if far <= pos then
    if blocks_oneway or not oneway then return far end
    return nil
  end
  if not oneway then return pos end
  return nil
end

-- Entry and exit times of [pos, pos + size] moving `delta` against [other, other + size2]
-- (strict overlap). nil when they never overlap on this axis.
local function interval_times(pos, size, delta, other, other_size)
  if delta > 0 then
    return (other - (pos + size)) / delta, (other + other_size - pos) / delta
  elseif delta < 0 then
    return (other + other_size - pos) / delta, (other - (pos + size)) / delta
  elseif pos < other + other_size and other < pos + size then
    return -HUGE, HUGE
  end
  return nil, nil
end

---Time of impact in [0, 1) of the box (x, y, w, h) moving (dx, dy) against the set, or
---nil. A candidate that overlaps the box at (start_x, start_y), where the move began,
---stops it at time 0 on each axis where the move goes deeper into it (its near face is
---inside the box), as in sweep.axis, and lets it leave otherwise; any other candidate
---that overlaps at (x, y) already (by rounding between steps of a long move) is met at
---time 0. Lists the candidates met at that time
---in set.touch and how each was met in set.normal: NORMAL_X when it came in across x
---last, NORMAL_Y across y, NORMAL_CORNER when both at the same instant. A oneway
---candidate is met only from above: moving down, its top at or below the box's bottom
---at the start, and entered across y.
function sweep.first_contact(set, start_x, start_y, x, y, w, h, dx, dy)
  local xs, ys, ws, hs, oneway = set.x, set.y, set.w, set.h, set.oneway
  local touch, normal = set.touch, set.normal
  local touched = 0
  local best = 1
  for i = 1, set.n do
    local bx, by, bw, bh = xs[i], ys[i], ws[i], hs[i]
    if start_x < bx + bw and bx < start_x + w and start_y < by + bh and by < start_y + h then
      if not oneway[i] then
        local deeper_x = (dx > 0 and bx > start_x) or (dx < 0 and bx + bw < start_x + w)
        local deeper_y = (dy > 0 and by > start_y) or (dy < 0 and by + bh < start_y + h)
        if deeper_x or deeper_y then
          if best > 0 then best = 0; touched = 0 end
          if deeper_x then
            touched = touched + 1
            touch[touched], normal[touched] = i, 1
          end
          if deeper_y then
            touched = touched + 1
            touch[touched], normal[touched] = i, 2
          end
        end
      end
    else
      local enter_x, exit_x = interval_times(x, w, dx, bx, bw)
      if enter_x then
        local enter_y, exit_y = interval_times(y, h, dy, by, bh)
        if enter_y then
          local enter = enter_x > enter_y and enter_x or enter_y
          local exit = exit_x < exit_y and exit_x or exit_y
          if enter < exit and exit > 0 and enter <= best then
            if enter < 0 then enter = 0 end
            if not oneway[i] or (dy > 0 and by >= start_y + h and enter_y >= enter_x) then
              if enter < best then best = enter; touched = 0 end
              if enter < 1 then
                touched = touched + 1
                touch[touched] = i
                normal[touched] = enter_x > enter_y and 1 or (enter_y > enter_x and 2 or 3)
              end
            end
          end
        end
      end
    end
  end
  set.touch_n = touched
  if touched == 0 then return nil end
  return best
end

return sweep
