-- budge.tilegrid: the one reader of tile grids, for world:add_tiles and
-- budge.tiles.merge. A grid is grid[row][col], a flat array of ids with opts.width
-- tiles per row, or a Tiled layer {width =, data =}; it is measured (form and size, with
-- errors that name the argument) and then read into a flat array of kinds indexed
-- (row - 1) * cols + col.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")

local format, error, type, ipairs, floor = string.format, error, type, ipairs, math.floor
local describe, is_finite = box.describe, box.is_finite

local tilegrid = {}

local EMPTY, SOLID, ONEWAY = 0, 1, 2
tilegrid.EMPTY, tilegrid.SOLID, tilegrid.ONEWAY = EMPTY, SOLID, ONEWAY

---Options shared by world:add_tiles and budge.tiles.merge.
---@class budge.LayerOptions
---@field x? number where the grid's top-left corner is (default 0)
---@field y? number
---@field width? integer tiles per row, for a flat grid
---@field is_solid? fun(id: any): boolean which ids are solid (default: any but nil, false, 0)
---@field is_oneway? fun(id: any): boolean which ids are oneway platforms (default: none)

-- A tile size: finite, > 0, and with a finite inverse (below 2^-1024 it overflows).
local function check_tile_size(size, name, level)
  if not is_finite(size) or size <= 0 then
    error(format("%s must be a finite number > 0, got %s", name, describe(size)), level + 1)
  end
  if not is_finite(1 / size) then
    error(format("%s must be > 2^-1024 (its inverse must be finite), got %s", name,
      describe(size)), level + 1)
  end
end

---Checks the options a tile layer shares wherever it is read: tile sizes > 0 with a finite
---inverse (a layer finds tiles by multiplying with it), opts a table or nil, opts.x and
---opts.y finite, opts.is_solid and opts.is_oneway functions.
---Errors at `level` (1 = the caller of the function that calls this).
---@param tile_width any
---@param tile_height any
---@param opts any
---@param level integer
---@return budge.LayerOptions opts the options, or a new empty table
function tilegrid.check_options(tile_width, tile_height, opts, level)
  check_tile_size(tile_width, "tile_width", level + 1)
  check_tile_size(tile_height, "tile_height", level + 1)
  if opts ~= nil and type(opts) ~= "table" then
    error(format("opts must be a table or nil, got %s", describe(opts)), level + 1)
  end
  opts = opts or {}
  for _, field in ipairs({"x", "y"}) do
    if opts[field] ~= nil and not is_finite(opts[field]) then
      error(format("opts.%s must be a finite number, got %s", field, describe(opts[field])),
        level + 1)
    end
  end
  for _, field in ipairs({"is_solid", "is_oneway"}) do
    if opts[field] ~= nil and type(opts[field]) ~= "function" then
      error(format("opts.%s must be a function or nil, got %s", field, describe(opts[field])),
        level + 1)
    end
  end
  return opts
end

-- The most tiles one grid may have: 2^24, a 4096x4096 map (its kinds take ~130 MB).
local MAX_TILES = 2 ^ 24
tilegrid.MAX_TILES = MAX_TILES

-- The largest whole-number key >= 1 of `t`, 0 when none: the length of an array that
-- may have holes, the same on every interpreter (`#` is not, once there are holes). Only
-- the maximum is kept, so the order pairs() visits keys in cannot reach a result.
local function extent(t)
  local n = 0
  for key in pairs(t) do
    if type(key) == "number" and key > n and key % 1 == 0 then n = key end
  end
  return n
end

local function check_size(cols, rows, level)
  if cols * rows > MAX_TILES then
    error(format("grid is %dx%d tiles, more than the %d one layer holds: split it into "
      .. "layers", cols, rows, MAX_TILES), level + 1)
  end
end

-- Checks a 2D grid: rows 1..extent are tables, all of one length (their last tile's
-- index), or none longer than `width` when it is given. Returns cols, rows.
local function check_rows(rows, width, level)
  local count = extent(rows)
  local first = rows[1]
  local cols = width or (type(first) == "table" and extent(first) or 0)
  for row = 1, count do
    local line = rows[row]
    if type(line) ~= "table" then
      error(format("grid[%d] must be a table (a row of tiles), got %s", row, describe(line)),
        level + 1)
    end
    local length = extent(line)
    if width ~= nil then
      if length > width then
        error(format("grid[%d] has a tile in column %d, beyond opts.width (%d)", row, length,
          width), level + 1)
      end
    elseif length ~= cols then
      error(format("grid[%d] has %d tiles but grid[1] has %d: every row must have the same "
        .. "length", row, length, cols), level + 1)
    end
  end
  check_size(cols, count, level + 1)
  return cols, count
end

-- LuaJIT: the grid is read once per add_tiles or update, so its readers stay interpreted.
-- One CI run of luajit (2.1.0-beta3) raised "grid[2] has 2 tiles but grid[1] has 2" from
-- a compiled check_rows that no rerun reproduced; interpreted, there is nothing to miscompile.
local jit = rawget(_G, "jit")
if jit and jit.off then
  jit.off(extent)
  jit.off(check_rows)
end

local function check_width(cols, message, level)
  if type(cols) ~= "number" or cols < 1 or cols % 1 ~= 0 then
    error(format(message, describe(cols)), level + 1)
  end
  if cols > MAX_TILES then
    error(format("a grid of %s tiles per row is more than the %d one layer holds: split it "
      .. "into layers", describe(cols), MAX_TILES), level + 1)
  end
end

---Measures the caller's grid without reading its ids: which form it is in and its size.
---A nil id is an empty tile wherever it stands: sizes come from the largest index
---present (or a Tiled layer's width and height, or opts.width), never from `#`. Errors
---(naming the argument "grid") at `level` for anything that is not a grid.
---@param source any grid[row][col], a flat array, or a Tiled layer {width =, height =, data =}
---@param width any opts.width: tiles per row of a flat array, or the longest row of a 2D grid
---@param level integer
---@return table|nil data the flat array of ids, or nil for a 2D grid
---@return integer cols
---@return integer rows
function tilegrid.measure(source, width, level)
  if type(source) ~= "table" then
    error(format("grid must be a table (grid[row][col], a flat array with opts.width, or a "
      .. "Tiled layer {width =, data =}), got %s", describe(source)), level + 1)
  end
  if width ~= nil then
    check_width(width, "opts.width must be a whole number >= 1 (tiles per row), got %s",
      level + 1)
  end
  local data, cols = source, width
  local tiled = type(source.data) == "table"
  if tiled then
    data, cols = source.data, source.width
    check_width(cols, "grid.width must be a whole number >= 1 (tiles per row of the Tiled "
      .. "layer), got %s", level + 1)
  end
  local count = extent(data)
  if count == 0 then return data, cols or 0, 0 end
  local first = data[1]
  for i = 2, count do
    if first ~= nil then break end
    first = data[i]
  end
  if not tiled and type(first) == "table" then
    local row_cols, rows = check_rows(source, width, level + 1)
    return nil, row_cols, rows
  end
  if cols == nil then
    check_width(cols, "opts.width must be a whole number >= 1 for a flat grid (tiles per "
      .. "row), got %s", level + 1)
  end
  local rows
  local height = tiled and source.height or nil
  if height ~= nil then
    check_width(height, "grid.height must be a whole number >= 1 (rows of the Tiled layer), "
      .. "got %s", level + 1)
    if count ~= cols * height then
      error(format("grid.data has %d tiles but grid.width x grid.height is %dx%d = %d", count,
        cols, height, cols * height), level + 1)
    end
    rows = height
  elseif count % cols ~= 0 then
    error(format("grid has %d tiles, which is not a whole number of rows of %d", count, cols),
      level + 1)
  else
    rows = count / cols
  end
  check_size(cols, rows, level + 1)
  -- whole numbers as integers on Lua 5.3+ (count / cols is a float there, and so is a
  -- width given as 4.0): a layer's indices, reach tables and hit counts stay integers
  return data, floor(cols), floor(rows)
end

---Reads the ids of a measured grid into `kinds` (EMPTY, SOLID or ONEWAY at
---(row - 1) * cols + col). `is_solid(id)` defaults to "any id but nil, false and 0"
---(0 is empty because Tiled and most tile maps use it so), `is_oneway(id)` to "never".
---@param source table the grid
---@param data table|nil what layer.measure returned
---@param cols integer
---@param rows integer
---@param is_solid? fun(id: any): boolean
---@param is_oneway? fun(id: any): boolean
---@param kinds integer[] filled in place
---@param ids? any[] filled in place with each non-empty tile's id (a filter is given it)
---@return integer[] kinds
function tilegrid.read(source, data, cols, rows, is_solid, is_oneway, kinds, ids)
  for row = 1, rows do
    local line = data == nil and source[row] or nil
    local base = (row - 1) * cols
    for col = 1, cols do
      local id
      if line then id = line[col] else id = data[base + col] end
      local kind = EMPTY
      if is_oneway and id ~= nil and is_oneway(id) then
        kind = ONEWAY
      elseif is_solid then
        if id ~= nil and is_solid(id) then kind = SOLID end
      elseif id and id ~= 0 then
        kind = SOLID
      end
      kinds[base + col] = kind
      if ids then ids[base + col] = kind ~= EMPTY and id or nil end
    end
  end
  return kinds
end

return tilegrid
