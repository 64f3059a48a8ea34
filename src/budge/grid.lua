-- budge.grid: the broad phase. Two structures, both plain arrays:
--
-- * a spatial hash over square cells for free boxes. Each cell is an array of records
--   in insertion order; a box spanning several cells is in each of them, and a query
--   visits each record once by stamping it. Cells are never freed: a world that keeps
--   its boxes in the same area stops allocating once every cell it uses exists.
-- * a tile layer: the caller's 2D grid flattened once into an array of kinds (0 empty,
--   1 solid, 2 oneway) read by index. No per-tile boxes, no hashing.
--
-- Nothing here iterates with pairs(); callers that return results sort them.

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")

local box = require(here .. ".box")

local floor, ceil = math.floor, math.ceil
local format, describe = string.format, box.describe
local stop_forward, stop_backward = sweep.stop_forward, sweep.stop_backward

local grid = {}

-- Cell keys are numbers: cx + cy * KEY_STRIDE + KEY_OFFSET is unique while |cx| and
-- |cy| < 2^25 (two billion pixels with 64 px cells either way from the origin). The
-- offset keeps every key far above the table's array part, so LuaJIT never has to
-- compile a lookup into a table that is part array, part hash.
local KEY_STRIDE = 2 ^ 26
local KEY_OFFSET = 2 ^ 25 * (KEY_STRIDE + 1)

local stamp_counter = 0

---A fresh stamp for one query: records visited in that query carry it.
function grid.next_stamp()
  stamp_counter = stamp_counter + 1
  return stamp_counter
end

local Hash = {}
Hash.__index = Hash

---@param cell_size number
function grid.new_hash(cell_size)
  return setmetatable({cell_size = cell_size, _cells = {}}, Hash)
end

---Registers `record` (any table; the hash writes its _cx0, _cy0, _cx1, _cy1 fields) in
---every cell the rectangle touches, edges included.
function Hash:insert(record, x, y, width, height)
  local size = self.cell_size
  local cx0, cy0 = floor(x / size), floor(y / size)
  local cx1, cy1 = floor((x + width) / size), floor((y + height) / size)
  record._cx0, record._cy0, record._cx1, record._cy1 = cx0, cy0, cx1, cy1
  local cells = self._cells
  for cy = cy0, cy1 do
    for cx = cx0, cx1 do
      local key = cx + cy * KEY_STRIDE + KEY_OFFSET
      local cell = cells[key]
      if cell == nil then
        cell = {}
        cells[key] = cell
      end
      cell[#cell + 1] = record
    end
  end
end

---Re-registers `record` if the rectangle now touches other cells than it did; cheap
---when it does not (an actor crosses a cell edge once every few moves).
function Hash:moved(record, x, y, width, height)
  local size = self.cell_size
  if floor(x / size) ~= record._cx0 or floor(y / size) ~= record._cy0
    or floor((x + width) / size) ~= record._cx1 or floor((y + height) / size) ~= record._cy1 then
    self:remove(record)
    self:insert(record, x, y, width, height)
  end
end

---Removes `record` from the cells it was inserted in.
function Hash:remove(record)
  local cells = self._cells
  for cy = record._cy0, record._cy1 do
    for cx = record._cx0, record._cx1 do
      local cell = cells[cx + cy * KEY_STRIDE + KEY_OFFSET]
      local count = #cell
      for i = 1, count do
        if cell[i] == record then
          -- keep insertion order inside the cell: shift, don't swap
          for j = i, count - 1 do cell[j] = cell[j + 1] end
          cell[count] = nil
          break
        end
      end
    end
  end
end

---Appends to `out` (from index n + 1) every record in the cells touched by the
---rectangle, once each, and returns the new count. Records come cell by cell in row
---order, and in insertion order inside a cell; callers sort what they return.
function Hash:collect(x, y, width, height, stamp, out, n)
  local size = self.cell_size
  local cx0, cy0 = floor(x / size), floor(y / size)
  local cx1, cy1 = floor((x + width) / size), floor((y + height) / size)
  local cells = self._cells
  for cy = cy0, cy1 do
    for cx = cx0, cx1 do
      local cell = cells[cx + cy * KEY_STRIDE + KEY_OFFSET]
      if cell then
        for i = 1, #cell do
          local record = cell[i]
          if record._stamp ~= stamp then
            record._stamp = stamp
            n = n + 1
            out[n] = record
          end
        end
      end
    end
  end
  return n
end


-- An axis probe: one box moving along one axis, filled by the caller (world.lua) and
-- read by the scans below, with the best stop found so far. Keeping these values in a
-- table instead of passing them down keeps each compiled loop small: LuaJIT aborts a
-- trace whose exits carry more live values than it can coalesce.
--   is_x, forward, pos, size, cross, cross_end, edge (pos + size), reach (where the
--   leading edge gets to), delta, blocks_oneway, actor, filter, touch (records out),
--   cols, rows (tiles out), best, touched
grid.probe = {touch = {}, cols = {}, rows = {}}

-- One record that spans the probe's path across: where it stops the probe, if it does,
-- and whether that is the best stop so far. Probe fields are read where they are used,
-- not hoisted into locals: fewer values live across the loop's exits keeps LuaJIT from
-- aborting the trace ("register coalescing too complex").
local function consider(probe, record, low, length)
  local stop
  if probe.forward then
    stop = stop_forward(low, probe.pos, probe.edge, probe.reach, probe.size, record.oneway,
      probe.blocks_oneway)
  else
    stop = stop_backward(low + length, probe.pos, probe.edge, probe.reach, record.oneway,
      probe.blocks_oneway)
  end
  if stop == nil then return end
  local best = probe.best
  if best ~= nil and (probe.forward and stop > best or not probe.forward and stop < best) then
    return
  end
  local filter = probe.filter
  if filter ~= nil and not filter(probe.actor, record.item) then return end
  local touched = probe.touched
  if stop ~= best then probe.best = stop; touched = 0 end
  touched = touched + 1
  probe.touch[touched] = record
  probe.touched = touched
end

local function scan_cell(cell, stamp, probe)
  for i = 1, #cell do
    local record = cell[i]
    if record._stamp ~= stamp then
      record._stamp = stamp
      if probe.is_x then
        if record.y < probe.cross_end and probe.cross < record.y + record.height then
          consider(probe, record, record.x, record.width)
        end
      elseif record.x < probe.cross_end and probe.cross < record.x + record.width then
        consider(probe, record, record.y, record.height)
      end
    end
  end
end

---Runs the probe over the hashed records (each with its box's x, y, width, height
---copied in, and `item` the box) in the cells (cx0..cx1, cy0..cy1): where the box stops,
---as sweep.stop_forward/backward decide, lands in probe.best, and the records that
---stop it there in probe.touch[1..probe.touched]. The probe's filter skips records.
function Hash:axis_stop(cx0, cy0, cx1, cy1, stamp, probe)
  local cells = self._cells
  -- one flat loop over the cells: fewer nested loops, fewer traces for LuaJIT
  local columns = cx1 - cx0 + 1
  local base = cx0 + cy0 * KEY_STRIDE + KEY_OFFSET
  for k = 0, columns * (cy1 - cy0 + 1) - 1 do
    local row = floor(k / columns)
    local cell = cells[base + (k - row * columns) + row * KEY_STRIDE]
    if cell then scan_cell(cell, stamp, probe) end
  end
end

---The cell range (cx0, cy0, cx1, cy1) a rectangle touches, edges included.
function Hash:cells_of(x, y, width, height)
  local size = self.cell_size
  return floor(x / size), floor(y / size), floor((x + width) / size), floor((y + height) / size)
end

---Number of cells the rectangle touches; lets a caller avoid walking a huge empty area.
function Hash:cell_count(x, y, width, height)
  local size = self.cell_size
  return (floor((x + width) / size) - floor(x / size) + 1)
    * (floor((y + height) / size) - floor(y / size) + 1)
end

grid.EMPTY, grid.SOLID, grid.ONEWAY = 0, 1, 2

---Checks the options a tile layer shares wherever it is read (world:add_tiles and
---budge.tiles.merge): tile sizes > 0, opts a table or nil, opts.x and opts.y finite,
---opts.is_solid and opts.is_oneway functions. Errors at `level` (1 = the caller of the
---function that calls this). Returns opts, or a new empty table.
function grid.check_layer_options(tile_width, tile_height, opts, level)
  if not box.is_finite(tile_width) or tile_width <= 0 then
    error(format("tile_width must be a finite number > 0, got %s", describe(tile_width)),
      level + 1)
  end
  if not box.is_finite(tile_height) or tile_height <= 0 then
    error(format("tile_height must be a finite number > 0, got %s", describe(tile_height)),
      level + 1)
  end
  if opts ~= nil and type(opts) ~= "table" then
    error(format("opts must be a table or nil, got %s", describe(opts)), level + 1)
  end
  opts = opts or {}
  for _, field in ipairs({"x", "y"}) do
    if opts[field] ~= nil and not box.is_finite(opts[field]) then
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

---Checks that `rows` is a 2D grid (rows[row][col]) whose rows all have the same length;
---errors at `level` naming the argument "grid". Returns the number of columns.
function grid.check_rows(rows, level)
  if type(rows) ~= "table" then
    error(format("grid must be a table of rows (grid[row][col]), got %s", describe(rows)),
      level + 1)
  end
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

---Flattens `rows` (rows[row][col]) into a tile layer. The caller has validated it.
---`is_solid(id)` and `is_oneway(id)` default to "any id but nil, false and 0" and "never".
function grid.new_tiles(rows, tile_width, tile_height, x, y, is_solid, is_oneway)
  local layer = {
    x = x, y = y, tile_width = tile_width, tile_height = tile_height,
    inverse_width = 1 / tile_width, inverse_height = 1 / tile_height,
    rows = #rows, cols = rows[1] and #rows[1] or 0,
    kinds = {}, grid = rows, _is_solid = is_solid, _is_oneway = is_oneway,
  }
  grid.read_tiles(layer)
  return layer
end

---(Re)reads the layer's source grid into its kinds array.
function grid.read_tiles(layer)
  local rows, kinds = layer.grid, layer.kinds
  local is_solid, is_oneway = layer._is_solid, layer._is_oneway
  local cols = layer.cols
  for row = 1, layer.rows do
    local line = rows[row]
    local base = (row - 1) * cols
    for col = 1, cols do
      local id = line[col]
      local kind = grid.EMPTY
      if is_oneway and id ~= nil and is_oneway(id) then
        kind = grid.ONEWAY
      elseif is_solid then
        if id ~= nil and is_solid(id) then kind = grid.SOLID end
      elseif id and id ~= 0 then
        kind = grid.SOLID
      end
      kinds[base + col] = kind
    end
  end
end


local SOLID, ONEWAY = grid.SOLID, grid.ONEWAY

-- The tile indices (0-based) whose span meets the open interval (from, to), clamped
-- to [0, count - 1]. Tile i covers [origin + i * size, origin + (i + 1) * size], the one
-- expression used for tile edges everywhere; a division that rounds onto a boundary is
-- caught by checking the result against it.
local function span(origin, size, inverse, count, from, to)
  local first = floor((from - origin) * inverse)
  if origin + first * size > from then first = first - 1 end
  local last = ceil((to - origin) * inverse) - 1
  if origin + (last + 1) * size < to then last = last + 1 end
  if first < 0 then first = 0 end
  if last > count - 1 then last = count - 1 end
  return first, last
end
grid.span = span

-- True when line `j` of tiles holds a tile that stops the box (rows or columns first..last
-- across it; `oneway_ok`: oneway tiles count).
local function line_blocks(kinds, base, cross_stride, first, last, oneway_ok)
  for i = first, last do
    local kind = kinds[base + i * cross_stride]
    if kind == SOLID or (kind == ONEWAY and oneway_ok) then return true end
  end
  return false
end

-- The scans start at the tile holding the box's trailing edge (a rounding can only move
-- that by one tile, onto or past a tile whose face is not a candidate anyway) and stop
-- at the first face beyond the leading edge's reach, or at the end of the layer. They
-- find the line of tiles only, in small functions, which LuaJIT compiles well; the
-- contacts on that line are listed afterwards. Return the line, its face and whether
-- oneway tiles counted on it.
local function scan_forward(kinds, stride, cross_stride, first, last, origin, tile, from, to,
                            pos, edge, far, blocks_oneway)
  for j = from, to do
    local near = origin + j * tile
    if near >= far then return nil end
    if near > pos then
      local ok = blocks_oneway and near >= edge
      if line_blocks(kinds, j * stride + 1, cross_stride, first, last, ok) then
        return j, near, ok
      end
    end
  end
  return nil
end

local function scan_backward(kinds, stride, cross_stride, first, last, origin, tile, from,
                             pos, edge, far, blocks_oneway)
  for j = from, 0, -1 do
    local high = origin + (j + 1) * tile
    if high <= far then return nil end
    if high < edge then
      local ok = blocks_oneway and high <= pos
      if line_blocks(kinds, j * stride + 1, cross_stride, first, last, ok) then
        return j, high, ok
      end
    end
  end
  return nil
end

-- Lists the tiles on line `line` that stop the box into probe.cols and probe.rows
-- (1-based); returns how many. Its own function so that the caller's values are not
-- live in this loop (LuaJIT aborts traces whose exits carry too many).
local function list_line(kinds, base, cross_stride, first, last, oneway_ok, line, is_x, probe)
  local out_cols, out_rows = probe.cols, probe.rows
  local found = 0
  for i = first, last do
    local kind = kinds[base + i * cross_stride]
    if kind == SOLID or (kind == ONEWAY and oneway_ok) then
      found = found + 1
      if is_x then out_cols[found], out_rows[found] = line + 1, i + 1
      else out_cols[found], out_rows[found] = i + 1, line + 1 end
    end
  end
  return found
end

---Nearest tile face the probe's box meets in the layer. Returns the face coordinate
---and how many tiles lie on it (their 1-based col and row written to probe.cols and
---probe.rows), or nil, 0. A face inside the box (the box overlaps a solid tile) counts
---too, so the caller can refuse to go deeper. Scans outward from the box and stops at
---the first face, so a huge move costs at most the layer's width.
function grid.tile_face(layer, probe)
  local is_x, pos, edge = probe.is_x, probe.pos, probe.edge
  local origin, tile, inverse, count, stride, cross_stride, first, last
  if is_x then
    origin, tile, inverse, count, stride, cross_stride =
      layer.x, layer.tile_width, layer.inverse_width, layer.cols, 1, layer.cols
    first, last = span(layer.y, layer.tile_height, layer.inverse_height, layer.rows,
      probe.cross, probe.cross_end)
  else
    origin, tile, inverse, count, stride, cross_stride =
      layer.y, layer.tile_height, layer.inverse_height, layer.rows, layer.cols, 1
    first, last = span(layer.x, layer.tile_width, layer.inverse_width, layer.cols,
      probe.cross, probe.cross_end)
  end
  if first > last then return nil, 0 end
  local line, face, oneway_ok
  if probe.forward then
    local from = floor((pos - origin) * inverse)
    if from < 0 then from = 0 end
    line, face, oneway_ok = scan_forward(layer.kinds, stride, cross_stride, first, last,
      origin, tile, from, count - 1, pos, edge, probe.reach, probe.blocks_oneway)
  else
    local from = ceil((edge - origin) * inverse) - 1
    if from > count - 1 then from = count - 1 end
    line, face, oneway_ok = scan_backward(layer.kinds, stride, cross_stride, first, last,
      origin, tile, from, pos, edge, probe.reach, probe.blocks_oneway)
  end
  if line == nil then return nil, 0 end
  return face, list_line(layer.kinds, line * stride + 1, cross_stride, first, last, oneway_ok,
    line, is_x, probe)
end

---Appends to the candidate set every non-empty tile that overlaps the rectangle
---(strictly), as a box with `other` = the layer. `id` orders it against other items.
function grid.gather_tiles(layer, x, y, width, height, set, id)
  local tile_width, tile_height = layer.tile_width, layer.tile_height
  local col0, col1 = span(layer.x, tile_width, layer.inverse_width, layer.cols, x, x + width)
  if col0 > col1 then return end
  local row0, row1 = span(layer.y, tile_height, layer.inverse_height, layer.rows, y, y + height)
  local kinds, cols = layer.kinds, layer.cols
  local n = set.n
  local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
  local set_cols, set_rows, ids = set.col, set.row, set.id
  for row = row0, row1 do
    local base = row * cols + 1
    for col = col0, col1 do
      local kind = kinds[base + col]
      if kind ~= 0 then
        n = n + 1
        xs[n], ys[n] = layer.x + col * tile_width, layer.y + row * tile_height
        ws[n], hs[n] = tile_width, tile_height
        oneway[n] = kind == ONEWAY
        other[n], set_cols[n], set_rows[n], ids[n] = layer, col + 1, row + 1, id
      end
    end
  end
  set.n = n
end

return grid
