-- The lab: moves actors with the method under test, times those moves, and judges each
-- one against the geometry, so a failure is seen where it happens.
--
-- A move is judged by fixtures/judge.lua, the judge the specs and the scenario
-- catalogue use: afterwards the actor
--   * overlaps a solid ("residual overlap"),
--   * was pushed across its path or back against it ("teleported"),
--   * went through one, its centre's straight path passing inside a solid: pushed out of
--     its far side ("wrong side") or not ("tunnelled"),
--   * or (discrete methods) stopped somewhere the exact sweep did not ("snagged").
-- The exact sweep's answer comes from moving the actor with axis_sweep first and putting
-- it back (for the discrete methods only: the others are judged without it).
--
-- Speed: timing each move would mostly time the clock (a C call in the middle of
-- compiled code costs more than a move). Instead, every few frames the lab replays the
-- moves of one frame in a tight loop, a few times over, and subtracts the same loop
-- without the moves; the HUD shows the median of the recent samples.
local budge = require("budge")
local judge = require("fixtures.judge")

local Lab = {}
Lab.__index = Lab

Lab.METHODS = budge.METHODS
Lab.CONTINUOUS = budge.CONTINUOUS
Lab.KINDS = judge.KINDS

local EPSILON = 1e-6
local MARK_FRAMES = 90
-- every 15 frames a sample of at least 2000 replayed moves; the median of the last 9
local SAMPLE_EVERY, SAMPLE_MOVES, SAMPLES = 15, 2000, 9

local clock = os.clock
if love and love.timer then clock = love.timer.getTime end

function Lab.new(method)
  local lab
  lab = setmetatable({
    world = budge.new_world(), method = method, solids = {}, layers = {},
    moves = 0, failures = {}, total_failures = 0, marks = {},
    frame_moves = {}, frame_count = 0, samples = {}, ticks = 0,
  }, Lab)
  -- what the judge asks of the scene: the lab's solids and tile layers
  lab.scene = {
    eps = EPSILON,
    overlaps = function(x, y, width, height) return lab:rect_blocked(x, y, width, height) end,
    through = function(x0, y0, x, y, width, height, pushed)
      if lab:centre_path_blocked(x0 + width / 2, y0 + height / 2, x + width / 2, y + height / 2) then
        return pushed and "wrong side" or "tunnelled"
      end
      return nil
    end,
  }
  return lab
end

-- The scene tells the lab what is solid: boxes (not oneway) and tile layers.
function Lab:add_solid(solid)
  self.world:add_solid(solid)
  if solid.wall_type ~= "oneway" then self.solids[#self.solids + 1] = solid end
  return solid
end

function Lab:add_tiles(rows, tile, opts)
  local layer = self.world:add_tiles(rows, tile, tile, opts)
  self.layers[#self.layers + 1] = {rows = rows, tile = tile,
    is_oneway = opts and opts.is_oneway}
  return layer
end

function Lab:add_actor(actor)
  return self.world:add_actor(actor)
end

-- True when the rectangle strictly overlaps a solid box or a solid tile (with width
-- and height 0: when the point is strictly inside one).
function Lab:rect_blocked(x, y, width, height)
  for i = 1, #self.solids do
    local s = self.solids[i]
    if x < s.x + s.width and s.x < x + width and y < s.y + s.height and s.y < y + height then
      return true
    end
  end
  for i = 1, #self.layers do
    local layer = self.layers[i]
    local tile = layer.tile
    for row = math.floor(y / tile), math.ceil((y + height) / tile) - 1 do
      for col = math.floor(x / tile), math.ceil((x + width) / tile) - 1 do
        local line = layer.rows[row + 1]
        local id = line and line[col + 1]
        if id and id ~= 0 and not (layer.is_oneway and layer.is_oneway(id)) then return true end
      end
    end
  end
  return false
end

function Lab:centre_path_blocked(x0, y0, x1, y1)
  local length = math.max(math.abs(x1 - x0), math.abs(y1 - y0))
  local steps = math.ceil(length * 2)
  for i = 1, steps - 1 do
    local t = i / steps
    if self:rect_blocked(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, 0, 0) then return true end
  end
  return false
end

function Lab:fail(kind, actor)
  self.failures[kind] = (self.failures[kind] or 0) + 1
  self.total_failures = self.total_failures + 1
  local marks = self.marks
  marks[#marks + 1] = {x = actor.x, y = actor.y, width = actor.width, height = actor.height,
    kind = kind, ttl = MARK_FRAMES}
  if #marks > 200 then table.remove(marks, 1) end
end

-- Moves `actor` by (dx, dy) with the lab's method; returns what world:move returns.
function Lab:move(actor, dx, dy)
  local world = self.world
  local x0, y0 = actor.x, actor.y
  local blocked_before = self:rect_blocked(x0, y0, actor.width, actor.height)
  local discrete = not Lab.CONTINUOUS[self.method]
  local reference_x, reference_y
  if discrete then -- where the exact sweep ends, for the snag check
    reference_x, reference_y = world:move(actor, dx, dy, "axis_sweep")
    actor.x, actor.y = x0, y0
    world:update(actor)
  end
  local x, y, n, hits = world:move(actor, dx, dy, self.method)
  self.moves = self.moves + 1
  local count = self.frame_count + 1
  local record = self.frame_moves[count] or {}
  record.actor, record.x, record.y, record.dx, record.dy = actor, x0, y0, dx, dy
  self.frame_moves[count], self.frame_count = record, count
  if blocked_before then return x, y, n, hits end -- already inside: judged at the last move
  local kind = judge.move(self.scene, x0, y0, actor.width, actor.height, dx, dy, x, y)
  if kind == nil and discrete
    and (math.abs(x - reference_x) > 0.5 or math.abs(y - reference_y) > 0.5) then
    kind = "snagged"
  end
  if kind then self:fail(kind, actor) end
  return x, y, n, hits
end

local function replay(self, with_moves, repeats)
  local world, method, list, count = self.world, self.method, self.frame_moves, self.frame_count
  local started = clock()
  for _ = 1, repeats do
    for i = 1, count do
      local record = list[i]
      local actor = record.actor
      -- a move reads its actor's position from the actor itself, and marks it for the
      -- world's next query, so the replay writes the start back without world:update
      actor.x, actor.y = record.x, record.y
      if with_moves then world:move(actor, record.dx, record.dy, method) end
    end
  end
  return clock() - started
end

-- Times this frame's moves (see the module comment), then puts every actor back where
-- its move left it.
function Lab:sample()
  local count = self.frame_count
  if count == 0 then return end
  local list, ends = self.frame_moves, {}
  for i = count, 1, -1 do -- the last move of an actor is where it ends this frame
    local actor = list[i].actor
    if not ends[actor] then ends[actor] = {actor.x, actor.y} end
  end
  local repeats = math.ceil(SAMPLE_MOVES / count)
  local with_moves = replay(self, true, repeats)
  local without = replay(self, false, repeats)
  for actor, position in pairs(ends) do
    actor.x, actor.y = position[1], position[2]
    self.world:update(actor)
  end
  local samples = self.samples
  samples[#samples + 1] = {seconds = math.max(0, with_moves - without), moves = repeats * count}
  if #samples > SAMPLES then table.remove(samples, 1) end
end

-- The median of the recent samples: one sample that caught LuaJIT compiling does not
-- move it.
function Lab:ns_per_move()
  local values = {}
  for i, sample in ipairs(self.samples) do values[i] = sample.seconds * 1e9 / sample.moves end
  if #values == 0 then return 0 end
  table.sort(values)
  return values[math.floor((#values + 1) / 2)]
end

-- "123 ns", or "(timing)" before the first sample (the first frames are not timed).
function Lab:speed_text()
  if #self.samples == 0 then return "(timing)" end
  return ("%.0f ns"):format(self:ns_per_move())
end

function Lab:tick()
  self.ticks = self.ticks + 1
  if self.timing and self.ticks % SAMPLE_EVERY == 0 then self:sample() end
  self.frame_count = 0
  local marks, kept = self.marks, 0
  for i = 1, #marks do
    local mark = marks[i]
    mark.ttl = mark.ttl - 1
    if mark.ttl > 0 then
      kept = kept + 1
      marks[kept] = mark
    end
  end
  for i = #marks, kept + 1, -1 do marks[i] = nil end
end

function Lab:summary()
  local parts = {}
  for _, kind in ipairs(Lab.KINDS) do
    if self.failures[kind] then parts[#parts + 1] = kind .. " " .. self.failures[kind] end
  end
  return #parts > 0 and table.concat(parts, ", ") or "none"
end

return Lab
