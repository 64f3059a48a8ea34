-- budge.tilegrid: the one reader of tile grids, for world:add_tiles and
-- budge.tiles.merge. A grid is grid[row][col], a flat array of ids with opts.width
-- tiles per row, or a Tiled layer {width =, data =}; it is measured (form and size, with
-- errors that name the argument) and then read into a flat array of kinds indexed
-- (row - 1) * cols + col.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")

local format, error, type, ipairs = string.format, error, type, ipairs
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

---Checks the options a tile layer shares wherever it is read: tile sizes > 0, opts a
---table or nil, opts.x and opts.y finite, opts.is_solid and opts.is_oneway functions.
---Errors at `level` (1 = the caller of the function that calls this).
---@param tile_width any
---@param tile_height any
---@param opts any
---@param level integer
---@return budge.LayerOptions opts the options, or a new empty table
function tilegrid.check_options(tile_width, tile_height, opts, level)
  if not is_finite(tile_width) or tile_width <= 0 then
    error(format("tile_width must be a finite number > 0, got %s", describe(tile_width)),
      level + 1)
  end
  if not is_finite(tile_height) or tile_height <= 0 then
    error(format("tile_height must be a finite number > 0, got %s", describe(tile_height)),
      level + 1)
  end
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

-- Checks that `rows` (a table whose first entry is a table) is a 2D grid whose rows
-- all have the same length. Returns the number of columns.
local function check_rows(rows, level)
  local cols
  for row = 1, #rows do
    local line = rows[row]
    if type(line) ~= "table" then
      error(format("grid[%d] must be a table (a row of tiles), got %s", row, describe(line)),
        level + 1)
    end
    if cols == nil then
      cols = #line
    elseif #line ~= cols then
      error(format("grid[%d] has %d tiles but grid[1] has %d: every row must have the same "
        .. "length", row, #line, cols), level + 1)
    end
  end
  return cols or 0
end

local function check_width(cols, message, level)
  if type(cols) ~= "number" or cols < 1 or cols % 1 ~= 0 then
    error(format(message, describe(cols)), level + 1)
  end
end

---Measures the caller's grid without reading its ids: which form it is in and its size.
---Errors (naming the argument "grid") at `level` for anything that is not a grid.
---@param source any grid[row][col], a flat array, or a Tiled layer {width =, data =}
---@param width any opts.width, for a flat array
---@param level integer
---@return table|nil data the flat array of ids, or nil for a 2D grid
---@return integer cols
---@return integer rows
function tilegrid.measure(source, width, level)
  if type(source) ~= "table" then
    error(format("grid must be a table (grid[row][col], a flat array with opts.width, or a "
      .. "Tiled layer {width =, data =}), got %s", describe(source)), level + 1)
  end
  local data, cols = source, width
  if type(source.data) == "table" then -- a Tiled layer
    data, cols = source.data, source.width
    check_width(cols, "grid.width must be a whole number >= 1 (tiles per row of the Tiled "
      .. "layer), got %s", level + 1)
  elseif type(source[1]) == "table" then
    return nil, check_rows(source, level + 1), #source
  elseif #source > 0 then
    check_width(cols, "opts.width must be a whole number >= 1 for a flat grid (tiles per "
      .. "row), got %s", level + 1)
  else
    return nil, 0, 0
  end
  local count = #data
  if count % cols ~= 0 then
    error(format("grid has %d tiles, which is not a whole number of rows of %d", count, cols),
      level + 1)
  end
  return data, cols, count / cols
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
---@return integer[] kinds
function tilegrid.read(source, data, cols, rows, is_solid, is_oneway, kinds)
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
    end
  end
  return kinds
end

return tilegrid
