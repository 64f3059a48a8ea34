-- examples/platformer/game.lua: the game's logic, with no drawing and no LÖVE: main.lua
-- draws it, headless.lua runs it for tests and benches. Every collision goes through
-- budge's public API:
--
--   world:add_tiles      the ground layer and the oneway platforms, read from the Tiled level
--   world:add_sensor     coins, spikes, checkpoints, the switch and the goal
--   world:add_actor      the player, the enemies and the bullets, each with a filter
--   actor.filter         what each meets and how: slide on ground, drop through a oneway
--                        tile while Down is held, cross coins, cross enemies (bullets)
--   world:move           every move; its hits say "on the ground", "a coin", "a wall"
--   world:move_solid     two moving platforms that carry the player, a door, a crusher
--   world:query_sweep    an enemy's ledge probe: is there ground ahead of its feet?
--   world:contacts       bullet against enemy and player against enemy, from both motions
local budge = require("budge")

local game = {}
local Game = {}
Game.__index = Game

local GRAVITY, MAX_FALL = 0.4, 8
local RUN, JUMP, CUT = 2.5, -7, -2
local COYOTE, BUFFER = 6, 6
local BULLET_SPEED, BULLET_LIFE, COOLDOWN = 36, 30, 12
local ENEMY_SPEED = 1

local function box(x, y, width, height)
  return {x = x, y = y, width = width, height = height}
end

---A new game on a Tiled level (the table level.lua returns).
---@param level table
---@return table game
function game.new(level)
  local self = setmetatable({world = budge.new_world({cell_size = 64}), frame = 0,
    coins = 0, total_coins = 0, kills = 0, total_enemies = 0, deaths = 0, causes = {},
    goal = false, inside = 0, enemies = {}, bullets = {}, platforms = {}, level = level,
    cooldown = 0, out = {}, out_t = {}, contacts = {}, drops = 0, coyote_jumps = 0,
    buffered_jumps = 0}, Game)
  -- the query filters, made once: what an enemy can stand on, and what no actor may be in
  self.is_floor = function(item)
    return item == self.ground or item == self.ledges or item.kind == "door"
  end
  self.is_solid = function(item)
    return item == self.ground or item.kind == "platform" or item.kind == "door"
      or item.kind == "crusher"
  end
  local world = self.world
  for _, layer in ipairs(level.layers) do
    if layer.type == "tilelayer" and layer.name == "ground" then
      -- a tile layer, not budge.tiles.merge: the ground's tiles are read by index, which
      -- the world bench measures fastest, and a filter is told each tile it meets
      self.ground = world:add_tiles(layer, level.tilewidth, level.tileheight)
    elseif layer.type == "tilelayer" and layer.name == "platforms" then
      self.ledges = world:add_tiles(layer, level.tilewidth, level.tileheight,
        {is_oneway = function(id) return id == 2 end})
    elseif layer.type == "objectgroup" then
      for _, object in ipairs(layer.objects) do self:spawn_object(object) end
    end
  end
  self:respawn()
  return self
end

function Game:spawn_object(object)
  local world, kind = self.world, object.type
  local item = box(object.x, object.y, object.width, object.height)
  item.kind = kind
  if kind == "spawn" then
    self.spawn_x, self.spawn_y = object.x, object.y
    self.checkpoint_x, self.checkpoint_y = object.x, object.y
    item.kind = "player"
    self.player = world:add_actor(item)
    self.player.filter = function(_, other, _, _, id) return self:player_meets(other, id) end
    self.player.on_crush = function() self:die("crusher") end
    self.player.vx, self.player.vy, self.player.facing = 0, 0, 1
  elseif kind == "coin" or kind == "spikes" or kind == "checkpoint" or kind == "switch"
    or kind == "goal" then
    world:add_sensor(item)
    if kind == "coin" then self.total_coins = self.total_coins + 1 end
  elseif kind == "enemy" then
    item.direction = -1
    item.filter = function(_, other) return self:enemy_meets(other) end
    self.enemies[#self.enemies + 1] = world:add_actor(item)
    self.total_enemies = self.total_enemies + 1
  elseif kind == "platform" then
    item.home, item.range, item.clock = object.x, object.properties.range, 0
    self.platforms[#self.platforms + 1] = world:add_solid(item)
  elseif kind == "door" then
    item.home, item.open = object.y, false
    self.door = world:add_solid(item)
  elseif kind == "crusher" then
    item.high, item.low, item.clock = object.y, object.properties.low, 0
    self.crusher = world:add_solid(item)
  end
end

-- The player's filter: ground and platforms block (a oneway tile lets the player drop
-- while Down is held), enemies are crossed (world:contacts reports them), bullets and
-- the player's own kind are ignored; sensors are crossed whatever this returns.
function Game:player_meets(other, id)
  if other == self.ledges and id == 2 and self.input.down then
    self.drops = self.drops + 1 -- (asked about a ledge tile it then falls through)
    return nil
  end
  if other.kind == "enemy" then return "cross" end
  if other.kind == "bullet" then return nil end
  return "slide"
end

-- An enemy's filter: it walks on the ground, turns at walls and at other enemies (it
-- stops against them, "slide": a "bounce" would carry it on past a ledge it just turned at).
function Game:enemy_meets(other)
  if other.kind == "enemy" then return "slide" end -- (stops where the other stands; turns)
  if other.kind == "bullet" or other.kind == "player" or other == self.player then return nil end
  if other.kind == "coin" or other.kind == "spikes" or other.kind == "checkpoint"
    or other.kind == "switch" or other.kind == "goal" then
    return nil
  end
  return "slide"
end

-- A bullet's filter: it crosses enemies and stops at anything solid.
local function bullet_meets(_, other)
  if other.kind == "enemy" then return "cross" end
  if other.kind == nil or other.kind == "platform" or other.kind == "door"
    or other.kind == "crusher" then
    return "touch"
  end
  return nil
end

function Game:respawn()
  local player, world = self.player, self.world
  player.x, player.y = self.checkpoint_x, self.checkpoint_y
  self.respawn_x = player.x
  player.vx, player.vy = 0, 0
  world:update(player)
  self.coyote, self.buffer, self.grounded = 0, 0, false
end

function Game:die(cause)
  if self.dead then return end -- (one death a frame, whatever else touches the player)
  self.deaths = self.deaths + 1
  self.causes[#self.causes + 1] = cause
  self.dead = cause
end

-- Is there ground just ahead of an enemy's leading foot?
function Game:ground_ahead(enemy)
  local foot = enemy.direction > 0 and enemy.x + enemy.width or enemy.x - 2
  local _, n = self.world:query_sweep(foot, enemy.y + enemy.height - 1, 2, 1, 0, 4, self.out,
    self.out_t, self.is_floor)
  return n > 0
end

function Game:update_enemies()
  local world = self.world
  for i = #self.enemies, 1, -1 do
    local enemy = self.enemies[i]
    if not self:ground_ahead(enemy) then enemy.direction = -enemy.direction end
    local _, _, n, hits = world:move(enemy, enemy.direction * ENEMY_SPEED, 1)
    for k = 1, n do
      if hits[k].nx ~= 0 then enemy.direction = hits[k].nx end
    end
  end
end

function Game:update_solids()
  local world = self.world
  for _, platform in ipairs(self.platforms) do
    -- 60 frames waiting at each end, |range| frames of travel between them at 1 px a frame
    local travel = math.abs(platform.range)
    platform.clock = (platform.clock + 1) % (2 * (60 + travel))
    local c, step = platform.clock, 0
    if c >= 60 and c < 60 + travel then step = 1 elseif c >= 120 + travel then step = -1 end
    if platform.range < 0 then step = -step end
    if step ~= 0 then world:move_solid(platform, step, 0) end
  end
  local crusher = self.crusher
  crusher.clock = (crusher.clock + 1) % 180
  local c = crusher.clock
  if c >= 60 and c < 76 then world:move_solid(crusher, 0, (crusher.low - crusher.high) / 16)
  elseif c >= 106 and c < 138 then world:move_solid(crusher, 0, (crusher.high - crusher.low) / 32) end
  local door = self.door
  if door.open and door.y > door.home - door.height then world:move_solid(door, 0, -2) end
end

function Game:update_player(input)
  local player, world = self.player, self.world
  player.vx = (input.right and RUN or 0) - (input.left and RUN or 0)
  if player.vx ~= 0 then player.facing = player.vx > 0 and 1 or -1 end
  local pressed = input.jump and not self.jump_held
  if pressed then self.buffer = BUFFER end
  if self.buffer > 0 and self.coyote > 0 then
    -- (counted: a jump off the ground's edge after leaving it, and one pressed before landing)
    if not self.grounded then self.coyote_jumps = self.coyote_jumps + 1 end
    if not pressed then self.buffered_jumps = self.buffered_jumps + 1 end
    player.vy, self.buffer, self.coyote = JUMP, 0, 0
  end
  if not input.jump and player.vy < CUT then player.vy = CUT end -- a short hop
  self.jump_held = input.jump
  player.vy = player.vy + GRAVITY
  if player.vy > MAX_FALL then player.vy = MAX_FALL end
  local _, _, n, hits = world:move(player, player.vx, player.vy)
  self.grounded = false
  for i = 1, n do
    local hit, other = hits[i], hits[i].other
    if self.dead then break end
    if hit.response == "cross" then
      if other.kind == "coin" and world:has(other) then
        world:remove(other)
        self.coins = self.coins + 1
      elseif other.kind == "spikes" then
        self:die("spikes")
      elseif other.kind == "checkpoint" then
        self.checkpoint_x, self.checkpoint_y = other.x, other.y + other.height - player.height
      elseif other.kind == "switch" then
        self.door.open = true
      elseif other.kind == "goal" then
        self.goal = true
      end
    elseif hit.ny < 0 then
      self.grounded = true
      player.vy = 0
    elseif hit.ny > 0 then
      player.vy = 0
    end
  end
  if self.grounded then self.coyote = COYOTE elseif self.coyote > 0 then self.coyote = self.coyote - 1 end
  if self.buffer > 0 then self.buffer = self.buffer - 1 end
  self.cooldown = self.cooldown > 0 and self.cooldown - 1 or 0
  if input.shoot and self.cooldown == 0 then
    self.cooldown = COOLDOWN
    local bullet = box(player.facing > 0 and player.x + player.width or player.x - 6,
      player.y + 4, 6, 4)
    bullet.kind, bullet.vx, bullet.life, bullet.filter = "bullet", player.facing * BULLET_SPEED,
      BULLET_LIFE, bullet_meets
    self.bullets[#self.bullets + 1] = world:add_actor(bullet)
  end
end

function Game:update_bullets()
  local world = self.world
  for i = #self.bullets, 1, -1 do
    local bullet = self.bullets[i]
    local _, _, n, hits = world:move(bullet, bullet.vx, 0)
    bullet.life = bullet.life - 1
    local stopped = bullet.life <= 0
    for k = 1, n do
      if hits[k].response == "touch" then stopped = true end
    end
    -- (taken out after world:contacts: a bullet that crossed an enemy on its way into the
    -- wall still kills it)
    bullet.stopped = stopped
  end
end

function Game:remove_stopped_bullets()
  local world = self.world
  for i = #self.bullets, 1, -1 do
    local bullet = self.bullets[i]
    if bullet.stopped then
      world:remove(bullet)
      table.remove(self.bullets, i)
    end
  end
end

local function drop(list, item)
  for i = #list, 1, -1 do
    if list[i] == item then table.remove(list, i) return end
  end
end

-- What touched during the frame, from both motions: a bullet that crossed an enemy kills
-- it (even when neither overlaps the other where they end), an enemy that met the player
-- kills the player.
function Game:resolve_contacts()
  local world = self.world
  local contacts, n = world:contacts(self.contacts)
  for i = 1, n do
    local item, other = contacts[i].item, contacts[i].other
    if item.kind == "bullet" and other.kind == "enemy" and world:has(other) then
      world:remove(other)
      drop(self.enemies, other)
      self.kills = self.kills + 1
      if world:has(item) then world:remove(item); drop(self.bullets, item) end
    elseif item == self.player and other.kind == "enemy" and world:has(other) then
      self:die("enemy")
    end
  end
end

-- Whether any actor ended the frame inside the ground or a solid (never, if budge is right).
function Game:check_inside()
  local world, solid = self.world, self.is_solid
  local function inside(a)
    local _, n = world:query_rect(a.x, a.y, a.width, a.height, self.out, solid)
    return n > 0
  end
  local any = inside(self.player)
  for i = 1, #self.enemies do any = inside(self.enemies[i]) or any end
  for i = 1, #self.bullets do any = inside(self.bullets[i]) or any end
  if any then self.inside = self.inside + 1 end
end

---One frame of the game at 1/60 s. `input` holds left, right, jump, down, shoot.
---@param input table
function Game:update(input)
  self.frame = self.frame + 1
  self.input = input
  self.dead = nil
  if not self.goal then
    self:update_solids()
    self:update_player(input)
    self:update_enemies()
    self:update_bullets()
    self:resolve_contacts()
    self:remove_stopped_bullets()
    if self.player.y > self.level.height * self.level.tileheight then self:die("fell") end
    if self.dead then self:respawn() end
  end
  self:check_inside()
end

---The one-line verdict of a run.
---@return string
function Game:verdict()
  return ("frames %d coins %d/%d kills %d/%d deaths %d (%s) goal %s inside %d drops %d "
    .. "coyote %d buffered %d respawn %s"):format(self.frame, self.coins, self.total_coins,
    self.kills, self.total_enemies, self.deaths, table.concat(self.causes, ","),
    tostring(self.goal), self.inside, self.drops, self.coyote_jumps, self.buffered_jumps,
    tostring(self.respawn_x))
end

---Reads an input script: a list of {first frame, last frame, "keys"}; returns a function
---frame -> input.
---@param segments table
---@return fun(frame: integer): table
function game.player_input(segments)
  local input = {}
  return function(frame)
    input.left, input.right, input.jump, input.down, input.shoot = false, false, false, false,
      false
    for _, segment in ipairs(segments) do
      if frame >= segment[1] and frame <= segment[2] then
        for key in segment[3]:gmatch("%a+") do input[key] = true end
      end
    end
    return input
  end
end

return game
