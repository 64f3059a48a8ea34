-- budge.hash: a spatial hash over square cells, for boxes that are not tiles.
--
-- The invariant: a record inserted with the rectangle (x, y, width, height) is in every
-- cell (cx, cy) with floor(x / size) <= cx <= floor((x + width) / size) and likewise on
-- y, exactly once each, and its [8] to [11] name that range (cx0, cy0, cx1, cy1). Inside
-- a cell records keep insertion order. Scans visit each record once by stamping it with
-- a number from the hash's own counter, so two hashes (two worlds) never disturb each
-- other. The axis scan of a packed hash (the world's solids: see hash.new) reads the
-- cells' packed copies of their records' boxes (the store) instead and stamps nothing: a
-- record met in two cells is added to the probe's touch list once, checked on a tie. The
-- store leaves a box out of the cells its far sides only touch (see packed_end).
--
-- The hash stores what it is given: it reads and writes only the fields declared in
-- budge.HashRecord. Cells are never freed, nor their room in the store: a world whose
-- boxes stay in one area stops allocating once every cell it uses exists (and has room
-- for the most boxes it has held at once). Nothing here iterates with pairs().
--
-- Bounded work: a record spanning more than BIG_CELLS (4096) cells is kept in a list of big
-- records instead of its cells, and a scan of a rectangle touching more cells than the
-- hash holds records walks the list of all records instead of the cells, so no call
-- walks more cells than it has records to find. Keys are exact while |cx| and |cy| stay
-- below 2^25, which the world's range (2^24 cells either way) keeps.

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")

local abs, floor, min, max = math.abs, math.floor, math.min, math.max
-- LuaJIT takes the branch-free forms of the scans (math.min compiles to no branch there);
-- Lua 5.1-5.4 the ones with comparisons.
local BRANCH_FREE = rawget(_G, "jit") ~= nil
local stop_forward, stop_backward = sweep.stop_forward, sweep.stop_backward
local power_of_two = sweep.power_of_two -- (see packed_end)

local hash = {}

-- Past its last record, the list of all records (_all) always holds two of these: a
-- record whose box starts at +inf, which no scan keeps. LuaJIT shaping: Hash:axis_stop's
-- scan of all the records of a small hash reads them too (PAD more turns of its loop).
-- LuaJIT starts a loop's own trace at the end of a turn and aborts it when the next turn
-- is the last ("leaving loop in root trace"); after two such aborts it unrolls the loop
-- into every trace that runs it instead, and a world of a few moving platforms has 2 to 8
-- solids. With the two more turns the loop keeps a trace of its own: `make bench-jit`'s
-- platformer 297 -> 253 KB of machine code with a budget that never runs out, 310 -> 269
-- at the default one (medians of 9, fresh runs interleaved, 2026-12-03); the example
-- game (`bench/game.lua --way default`, 5 runs) 33.6 -> 29.6 us per frame, 287 -> 261
-- KB. Lua 5.1-5.4 read n records (PAD 0). budge.bump's nearest does the same.
-- (budge.bump's nearest pads its region with the same record: its mark, [14], is +inf)
local SENTINEL = {math.huge, math.huge, 0, 0, false, 0, false, 0, 0, 0, 0, 0, 0, math.huge,
  _stamp = 0}
local PAD = BRANCH_FREE and 2 or 0
hash.SENTINEL = SENTINEL

---What the hash reads and writes on a record. A record carries a copy of its box in its
---array part ([1] x, [2] y, [3] width, [4] height), read by the scans that test boxes
---(Hash:axis_stop, Hash:collect_overlapping, Hash:collect_touching); Hash:collect needs
---only the cell and stamp fields. (The array part: the four values in one run of memory, not four hash nodes
---spread over a record's 16 or 32: `luajit bench/world.lua --way W --count 10000`, 7
---fresh runs each, interleaved, 2026-12-02: tiles 259 -> 222 ns per move, budge.bump
---2939 -> 2191.)
---@class budge.HashRecord
---@field item any what the record stands for
---@field [1] number the box: x, copied in
---@field [2] number y
---@field [3] number width
---@field [4] number height
---@field [8] integer the cells the record is in, cx0 (written by the hash; [5] to [7] are
---the world's, see budge.Record)
---@field [9] integer cy0
---@field [10] integer cx1
---@field [11] integer cy1
---@field [12]? integer in a packed hash, the last column of its entries in the store (cx1,
---or cx1 - 1 when its right side is on cx1's low edge: see packed_end; a big record has
---no entries, and this is the column they would end at)
---@field [13]? integer the last row of its entries there
---@field oneway? boolean blocks only moves down onto its top (read by Hash:axis_stop)
---@field removed? boolean taken out of its world while a move runs: scans skip it (a packed
---hash's scans by its entries, which its owner empties then: solids.retire)
---@field package _stamp integer the last scan that visited it (written by the hash)
---@field package _slot integer its place in the hash's list of all records
---@field package _big_slot? integer its place in the list of big records, when it is one

---@class budge.Hash
---@field cell_size number side of a cell
---@field package _cells table<number, budge.HashRecord[]> cell key -> records, in insertion
---order (with `pack`, their boxes packed, in a packed hash)
---@field package _stamp integer the counter scans take their stamps from
---@field package _all budge.HashRecord[] every record, in no particular order, then two
---sentinels (SENTINEL)
---@field package _n integer how many (#_all, kept as a field: `#` is a search on LuaJIT)
---@field package _big budge.HashRecord[] the records spanning more than BIG_CELLS cells
---@field package _packed boolean keeps a packed copy of its records' boxes (the store)
---@field package _exact boolean its cell size is a power of two (see packed_end)
---@field package _store any[] packed hashes: every cell's packed boxes, in one array
---@field package _span table<integer, integer> for a cell's slot, at 2 * slot - 1 where its
---first entry in the store starts (its entries: see hash.new), at 2 * slot where its last
---entry starts (an empty cell: less than its first): the two side by side, in one cache
---line (in two arrays, two lines from far apart per cell a scan visits)
---@field package _room table<integer, integer> slot -> where the store's room for the
---cell ends (the next cell's room may start there)
---@field package _top integer where the store's first unused room starts
---@field package _gx0 integer the cells with a slot: columns _gx0.._gx1, rows _gy0.._gy1,
---the slot of (cx, cy) (cy - _gy0) * _gw + (cx - _gx0) + 1 (see regrid)
---@field package _gy0 integer
---@field package _gx1 integer
---@field package _gy1 integer
---@field package _gw integer
---@field package _cx integer[] the columns of the cells that exist, in the order they were made
---@field package _cy integer[] their rows
local Hash = {}
Hash.__index = Hash

-- Cell keys are numbers: cx + cy * KEY_STRIDE + KEY_OFFSET is unique while |cx| and
-- |cy| < 2^25 (two billion pixels with 64 px cells either way from the origin).
-- LuaJIT shaping: the offset keeps every key far above the table's array part: with
-- keys from 0 up, LuaJIT's lookups mix the array and hash parts and moves among hashed
-- boxes take 1365 ns instead of 1004, merged boxes 1158 instead of 845 (`luajit
-- bench/world.lua --profile boxes` and `--profile merged`, median of 5, 2026-12-01).
local KEY_STRIDE = 2 ^ 26
local KEY_OFFSET = 2 ^ 25 * (KEY_STRIDE + 1)
local BIG_CELLS = 4096
-- Hash:axis_stop scans every record of a hash of at most this many instead of its cells.
local SMALL = 8

---A new, empty hash. With `packed`, the hash keeps beside its cells a packed copy of
---their records' boxes, as inserted, which Hash:axis_stop reads instead of the records:
---the world's solids (world.lua), whose boxes change only by a remove and an insert, and
---budge.bump's items (their own boxes written over their entries by Hash:repack). All
---the cells' copies are in one flat array, the store: a cell's entries one after the
---other, in the cell's order, six values each (an entry starting at b: b + 1 x, b + 2 y,
---b + 3 right, b + 4 bottom, b + 5 the record's id ([6], or 1 without one), negated when
---it is oneway, b + 6 the record, or with `payload` the record's [payload]: the world's
---solids keep their items there, and a hit with one is written from its entry alone,
---with no read of the record), from _span[2 * slot - 1]
---to _span[2 * slot], with room up to _room[slot]. A cell's slot is a number worked out from its
---column and row: while the cells in use fill a good part of the rectangle around them,
---an index into that rectangle (the three tables are arrays, read by index), otherwise
---the cell's key (tables with a hash part: see regrid).
---Speed: the scan reads, per cell, three numbers of small dense arrays and the cell's run
---of the store, where a pack per cell found by its key in a table (the layout before)
---read the key's hash node, the pack's header and its array, three places in memory at
---random. `luajit bench/world.lua --way W --count N`, 5 fresh runs each, interleaved
---with the tree before, 2026-12-03, medians in ns per move: box per tile 488 -> 415 at N =
---1000, 610 -> 513 at 10000; merged boxes 449 -> 411 and 566 -> 555. (A first try of the
---store with the slot looked up by the cell's key, 300 frames: about half the gain of
---the rectangle's index, measured against it: 597 against 574 ns, 699 against 615.)
---Speed: the scan reads one array per cell, where each record is a table of its own
---with a hash part (an actor's 405 bytes on LuaJIT, 530 on Lua 5.4, 850 on both before
---its box, kind, mark and cells moved to the array part: a world bench scene of 8000
---boxes does not fit in the cache the scan reads through), and writes no stamp into the
---records it passes.
---Speed (payload): `luajit bench/world.lua --way boxes --count 10000`, the box per tile
---at 10000 actors, where reading each hit's record for its item and id was a cache miss:
---see the CHANGELOG's entry "Box hits from the store".
---@param cell_size number > 0, checked by the caller
---@param packed? boolean
---@param payload? integer the slot of a record its entries and Hash:axis_stop's touch
---list hold instead of the record (unique to the record in this hash)
---@return budge.Hash
function hash.new(cell_size, packed, payload)
  return setmetatable({cell_size = cell_size, _cells = {}, _stamp = 0,
    _all = {SENTINEL, SENTINEL}, _n = 0, _big = {}, _packed = packed == true,
    _payload = payload or false,
    _exact = power_of_two(cell_size), _store = {}, _span = {}, _room = {}, _top = 0,
    _gx0 = 0, _gy0 = 0, _gx1 = -1, _gy1 = -1, _gw = 0, _cx = {}, _cy = {}}, Hash)
end

---A fresh stamp for one scan: records visited in that scan carry it.
---@return integer
function Hash:next_stamp()
  local stamp = self._stamp + 1
  self._stamp = stamp
  return stamp
end

---The cell range (cx0, cy0, cx1, cy1) a rectangle touches, edges included.
---@param x number
---@param y number
---@param width number
---@param height number
---@return integer cx0, integer cy0, integer cx1, integer cy1
function Hash:cells_of(x, y, width, height)
  local size = self.cell_size
  return floor(x / size), floor(y / size), floor((x + width) / size), floor((y + height) / size)
end

---Number of cells the rectangle touches; lets a caller avoid walking a huge empty area.
---@param x number
---@param y number
---@param width number
---@param height number
---@return integer
function Hash:cell_count(x, y, width, height)
  local cx0, cy0, cx1, cy1 = self:cells_of(x, y, width, height)
  return (cx1 - cx0 + 1) * (cy1 - cy0 + 1)
end

-- The store (packed hashes) --------------------------------------------------------

-- A rectangle of slots holds at most this many cells more than 8 per cell in use: past
-- that, slots are the cells' keys (the store's three tables then have a hash part).
local DENSE_CELLS = 4096
-- The rectangle of cells whose slot is their key: any cell the world's range allows
-- (with these, (cy - SPARSE_Y0) * KEY_STRIDE + (cx - SPARSE_X0) + 1 is the key).
local SPARSE_X0, SPARSE_Y0, SPARSE_END = 1 - 2 ^ 25, -2 ^ 25, 2 ^ 25 - 1

-- Lays the store out again with slots for the cells (cx0..cx1, cy0..cy1) as well as for
-- those that exist: the cells in the order they were made, each with room for its
-- entries and no more (so it compacts the store too). While the cells in use fill a good
-- part of the rectangle around them (at most DENSE_CELLS + 8 per cell), a cell's slot is
-- its index in that rectangle (grown by a quarter on each side that grows, so that a map
-- added tile by tile lays out a few times, not once per row), else its key, for good.
local function regrid(self, cx0, cy0, cx1, cy1)
  local gx0, gy0, gw = self._gx0, self._gy0, self._gw
  local nx0, ny0, nx1, ny1, nw = SPARSE_X0, SPARSE_Y0, SPARSE_END, SPARSE_END, KEY_STRIDE
  local xs, ys = self._cx, self._cy
  local n = #xs
  if gw ~= KEY_STRIDE then
    if self._gx1 < gx0 then -- (no cell yet)
      nx0, ny0, nx1, ny1 = cx0, cy0, cx1, cy1
    else
      nx0, ny0 = min(gx0, cx0), min(self._gy0, cy0)
      nx1, ny1 = max(self._gx1, cx1), max(self._gy1, cy1)
      local grow_x, grow_y = floor((nx1 - nx0) / 4) + 1, floor((ny1 - ny0) / 4) + 1
      if nx0 < gx0 then nx0 = nx0 - grow_x end
      if nx1 > self._gx1 then nx1 = nx1 + grow_x end
      if ny0 < gy0 then ny0 = ny0 - grow_y end
      if ny1 > self._gy1 then ny1 = ny1 + grow_y end
    end
    nw = nx1 - nx0 + 1
    if nw * (ny1 - ny0 + 1) > DENSE_CELLS + 8 * (n + (cx1 - cx0 + 1) * (cy1 - cy0 + 1)) then
      nx0, ny0, nx1, ny1, nw = SPARSE_X0, SPARSE_Y0, SPARSE_END, SPARSE_END, KEY_STRIDE
    end
  end
  local old_store, old_span = self._store, self._span
  local store, span, room = {}, {}, {}
  if nw ~= KEY_STRIDE then
    for slot = 1, nw * (ny1 - ny0 + 1) do
      span[2 * slot - 1], span[2 * slot], room[slot] = 0, -6, 0
    end
  end
  local top = 0
  for i = 1, n do
    local cx, cy = xs[i], ys[i]
    local from, to = (cy - gy0) * gw + (cx - gx0) + 1, (cy - ny0) * nw + (cx - nx0) + 1
    local b, e = old_span[2 * from - 1], old_span[2 * from]
    for j = 1, e + 6 - b do store[top + j] = old_store[b + j] end
    span[2 * to - 1], span[2 * to] = top, top + e - b
    top = top + e + 6 - b
    room[to] = top
  end
  self._store, self._span, self._room = store, span, room
  self._top = top
  self._gx0, self._gy0, self._gx1, self._gy1, self._gw = nx0, ny0, nx1, ny1, nw
end

-- The last column (or row) of a packed hash's entries for a box from cell c0 whose far
-- side is at `far`: the cell that holds the far side, but when the far side is on that
-- cell's low edge, the one before (at least c0). So the store holds a box in the cells
-- it meets with more than an edge (its near sides included, its far sides not), where
-- the records' cells include both edges. Nothing is lost: a far side stops a move back
-- only when it lies beyond the move's reach (sweep.stop_backward: a move that ends on it
-- is not stopped by it), so a scan from the reach's cell meets the cell before it; and a
-- box strictly overlaps the move across in a cell it meets with more than an edge.
-- Speed: a grid of tiles lies on the edges of a quarter of the cells around it on each
-- axis, and the world bench's box per tile scanned 7.35 entries per scan in 1.42 cells
-- (64 px cells) before and 4.75 after; merged boxes 5.43 and 3.54 (bench/world.lua's
-- scene, 10000 actors). `luajit bench/world.lua --way W --count N`, 5 fresh runs each,
-- interleaved with the tree before, 2026-12-04, medians in ns per move: box per tile
-- 400 -> 390 at N = 100, 553 -> 503 at 10000; merged boxes 381 -> 364 and 538 -> 504.
-- Exactness: only with a cell size that is a power of two, where far / size is exact (a
-- far side on the edge is then exactly c * size, and every number below it divides to
-- less than c); else the cell that holds the far side, as the records' cells. With 7.3,
-- a box whose right side was 124.10000000000001 (/ 7.3 rounds to 17) had no entry in
-- column 17, and a move back from 200 to 124.09999999999999, whose reach divides to 17
-- too, passed into it (found by a hostile review, 2026-12-05; spec/world_spec.lua).
local function packed_end(c0, far, size, exact)
  local q = far / size
  local c = floor(q)
  if exact and c == q and c ~= 0 and c * size == far then return max(c0, c - 1) end
  return c
end

-- The slot of the cell (cx, cy) (the scans work it out the same way, from locals).
local function slot_of(self, cx, cy)
  return (cy - self._gy0) * self._gw + (cx - self._gx0) + 1
end

-- Appends an entry to the cell (cx, cy); a cell with no room left moves to the top of
-- the store with room for twice its entries. Its old room is left behind until the next
-- lay-out (regrid: a box outside the slots' rectangle): the rooms left behind add up to
-- less than the rooms in use, so the store holds less than four times the most entries
-- each cell has held at once (a cell's room: four entries at least). (Not laid out
-- again for them alone: a cell that keeps growing would be compacted, then moved again at
-- its next entry.)
-- Every value of the store up to its top is set (false where no entry is): the array
-- stays one run of memory, and a trace's writes into it never leave its array part (with
-- nil there, the platformer of `luajit bench/jit.lua` aborted 242 side traces a run at
-- the writes below, "register coalescing too complex").
local function pack_add(self, cx, cy, x, y, right, bottom, flag, entry)
  local slot = slot_of(self, cx, cy)
  local store, span = self._store, self._span
  local base = span[2 * slot] + 6
  if base >= self._room[slot] then
    local first, top = span[2 * slot - 1], self._top
    local used = base - first
    local room = top + max(used * 2, 24)
    for j = 1, used do store[top + j], store[first + j] = store[first + j], false end
    for j = top + used + 1, room do store[j] = false end
    span[2 * slot - 1], self._room[slot], self._top = top, room, room
    base = top + used
  end
  store[base + 1], store[base + 2], store[base + 3] = x, y, right
  store[base + 4], store[base + 5], store[base + 6] = bottom, flag, entry
  span[2 * slot] = base
end

-- The index before `record`'s entry in the store, searched from `base` (the index before
-- an entry of its cell). `~=` on Lua 5.1-5.4, where rawequal is a call into C per entry
-- (budge.bump's repack at 10000 items: 75564 -> 71326 instructions per move, `lua5.4
-- bench/instructions.lua --way bump_boxes --count 10000 --frames 5 --lua lua5.4`,
-- 2026-12-05): the records are budge's own tables, with no metatable, so `~=` is raw
-- there (a false where the store has no entry compares unequal as well).
-- find_item is the rawequal search, which every interpreter uses for a hash whose entries
-- hold a game's items (hash.new's payload): those may have an __eq that `~=` would call.
local function find_item(store, base, item)
  while not rawequal(store[base + 6], item) do base = base + 6 end
  return base
end
local find_entry = BRANCH_FREE and find_item or function(store, base, entry)
  while store[base + 6] ~= entry do base = base + 6 end
  return base
end
-- The search for this hash's entries: find_item on LuaJIT (where both are it: no read of
-- the hash's payload on budge.bump's every move) and for a payload's items.
local function finder(self)
  if BRANCH_FREE or self._payload then return find_item end
  return find_entry
end

-- What the store's entries of `record` hold in their last slot (see hash.new).
local function entry_of(self, record)
  local payload = self._payload
  if payload then return record[payload] end
  return record
end

-- Takes `record`'s entry out of the cell (cx, cy), keeping the others' order.
local function pack_remove(self, cx, cy, record)
  local slot = slot_of(self, cx, cy)
  local store, span = self._store, self._span
  local e, from = span[2 * slot], span[2 * slot - 1]
  from = finder(self)(store, from, entry_of(self, record))
  for j = from + 1, e do store[j] = store[j + 6] end
  for j = e + 1, e + 6 do store[j] = false end
  span[2 * slot] = e - 6
end

---Registers `record` in every cell the rectangle touches, edges included.
---@param record budge.HashRecord
---@param x number
---@param y number
---@param width number
---@param height number
function Hash:insert(record, x, y, width, height)
  local cx0, cy0, cx1, cy1 = self:cells_of(x, y, width, height)
  record[8], record[9], record[10], record[11] = cx0, cy0, cx1, cy1
  local all = self._all
  local slot = self._n + 1
  all[slot], record._slot, self._n = record, slot, slot
  all[slot + 1], all[slot + 2] = SENTINEL, SENTINEL
  local right, bottom = x + width, y + height
  local flag, entry = record[6] or 1, entry_of(self, record) -- (the entries' last two)
  if record.oneway == true then flag = -flag end
  local size, exact, packed = self.cell_size, self._exact, self._packed
  local px1, py1 = packed_end(cx0, right, size, exact), packed_end(cy0, bottom, size, exact)
  -- (a big record too: it has no entries, but budge.bump reads the range they would have)
  if packed then record[12], record[13] = px1, py1 end
  if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > BIG_CELLS then
    local big = self._big
    local big_slot = #big + 1
    big[big_slot], record._big_slot = record, big_slot
    return
  end
  -- LuaJIT shaping: one flat loop over the cells (as in collect), not nested loops of one
  -- to three steps each, which LuaJIT unrolls into every trace that moves a record across
  -- a cell edge. budge.bump's moves (luajit bench/world.lua --way bump_boxes --count 1000,
  -- 5 fresh runs) needed 398 KB of machine code instead of 434, flushing 3
  -- times instead of 4; make bench-jit's platformer 738 KB instead of 798 (medians of 5,
  -- 2026-12-01).
  local cells = self._cells
  if packed and (cx0 < self._gx0 or cy0 < self._gy0 or cx1 > self._gx1 or cy1 > self._gy1) then
    regrid(self, cx0, cy0, cx1, cy1)
  end
  local columns = cx1 - cx0 + 1
  for k = 0, columns * (cy1 - cy0 + 1) - 1 do
    local row = floor(k / columns)
    local cx, cy = cx0 + (k - row * columns), cy0 + row
    local key = cx + cy * KEY_STRIDE + KEY_OFFSET
    local cell = cells[key]
    if cell == nil then
      cell = {}
      cells[key] = cell
      if packed then
        local made = #self._cx + 1
        self._cx[made], self._cy[made] = cx, cy
        if self._gw == KEY_STRIDE then -- (a rectangle's slots start empty; a key's is made here)
          local top = self._top
          self._span[2 * key - 1], self._span[2 * key], self._room[key] = top, top - 6, top
        end
      end
    end
    cell[#cell + 1] = record
    if packed and cx <= px1 and cy <= py1 then
      pack_add(self, cx, cy, x, y, right, bottom, flag, entry)
    end
  end
end

local function unlist(list, record, field, count)
  local slot = record[field]
  local last = list[count]
  list[slot], last[field] = last, slot
  list[count] = nil
  record[field] = nil
end

-- Takes `record` out of one cell, keeping the others' insertion order (shift, don't
-- swap); returns where it was in the cell.
local function unlist_cell(cell, record)
  local count = #cell
  for i = 1, count do
    if cell[i] == record then
      for j = i, count - 1 do cell[j] = cell[j + 1] end
      cell[count] = nil
      return i
    end
  end
end

---Removes `record` from the hash.
---@param record budge.HashRecord
function Hash:remove(record)
  local all, n = self._all, self._n
  unlist(all, record, "_slot", n)
  all[n], all[n + 2] = SENTINEL, nil -- (the two sentinels move down one)
  self._n = n - 1
  if record._big_slot then unlist(self._big, record, "_big_slot", #self._big) return end
  local cells, packed = self._cells, self._packed
  local cx0, cy0 = record[8], record[9]
  local columns = record[10] - cx0 + 1
  local px1, py1 = record[12], record[13] -- (its entries' last column and row: see insert)
  for k = 0, columns * (record[11] - cy0 + 1) - 1 do -- (one flat loop: see insert)
    local row = floor(k / columns)
    local cx, cy = cx0 + (k - row * columns), cy0 + row
    unlist_cell(cells[cx + cy * KEY_STRIDE + KEY_OFFSET], record)
    if packed and cx <= px1 and cy <= py1 then pack_remove(self, cx, cy, record) end
  end
end

-- Hash:moved's re-registration. LuaJIT shaping: left to the interpreter (remove's and
-- insert's loops still compile their own traces). Compiled into the loop of
-- actors.rehash, each way into it was a side trace carrying remove and insert, their short
-- loops unrolled, up to insert's loop: 3.0-3.5 KB of machine code each, about eight a run
-- of `luajit bench/game.lua` (from `jit.attach`'s trace events). With it interpreted the
-- play-through needed 238 KB instead of 251 (median of 12 runs, each its own process,
-- interleaved, 2026-12-08; carry.move_solid and solids.gather_all in the interpreter in
-- both); bench/contacts.lua's moves (1000 walkers re-registered before each bullet's
-- filtered move, `--budget large`) took 1329 ns per actor instead of 1261 (7 runs: within
-- the machine's noise).
local function reregister(self, record, x, y, width, height)
  self:remove(record)
  self:insert(record, x, y, width, height)
end
do
  local jit = rawget(_G, "jit")
  if jit and jit.off then jit.off(reregister) end
end

---Re-registers `record` if the rectangle now touches other cells than it did; cheap
---when it does not (an actor crosses a cell edge once every few moves).
---@param record budge.HashRecord
---@param x number
---@param y number
---@param width number
---@param height number
function Hash:moved(record, x, y, width, height)
  local cx0, cy0, cx1, cy1 = self:cells_of(x, y, width, height)
  -- (a packed hash's cells hold a copy of the box: it is inserted again whatever moved)
  if cx0 ~= record[8] or cy0 ~= record[9] or cx1 ~= record[10] or cy1 ~= record[11]
    or self._packed then
    reregister(self, record, x, y, width, height)
  end
end

---In a packed hash, writes the box (x, y, right, bottom) over the record's entries in the
---store, its cells unchanged: a record whose cells are those of a box around its own
---(budge.bump's loose cells) keeps its own box there, for Hash:collect_overlapping. (A
---record spanning more than BIG_CELLS cells has no entries: nothing to do.)
---@param record budge.HashRecord
---@param x number
---@param y number
---@param right number
---@param bottom number
function Hash:repack(record, x, y, right, bottom)
  if record._big_slot then return end
  local store, span, entry = self._store, self._span, entry_of(self, record)
  local cx0, cy0 = record[8], record[9]
  local columns = record[12] - cx0 + 1
  for k = 0, columns * (record[13] - cy0 + 1) - 1 do -- (one flat loop: see insert)
    local row = floor(k / columns)
    local slot = slot_of(self, cx0 + (k - row * columns), cy0 + row)
    local base = finder(self)(store, span[2 * slot - 1], entry)
    store[base + 1], store[base + 2], store[base + 3], store[base + 4] = x, y, right, bottom
  end
end

-- Appends to `out` the records of list[1..count] whose cells meet (cx0..cx1, cy0..cy1).
local function list_touching(list, count, cx0, cy0, cx1, cy1, out, n)
  for i = 1, count do
    local record = list[i]
    if record[8] <= cx1 and cx0 <= record[10] and record[9] <= cy1
      and cy0 <= record[11] then
      n = n + 1
      out[n] = record
    end
  end
  return n
end

---False when no record can touch the rectangle from (x0, y0) to (x1, y1) (its far sides
---as given: see collect_between): a rectangle within 2x2 cells whose cells are all empty
---(and no big record); true otherwise (look with collect_between). No loop:
---a move asks it about sparse things (sensors) and most often goes no further.
---LuaJIT shaping: without this test, collecting the sensors at every phase of every move
---made bench/contacts.lua's 1000 walkers compile 753 traces and 1372 KB of machine code
---(238 KB without sensors) and moves took 763 ns instead of 314 with a budget that never
---runs out (its loops' exits each carry a copy of the rest of the move).
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@return boolean
function Hash:occupied_between(x0, y0, x1, y1)
  if self._n == 0 then return false end
  if self._big[1] then return true end
  local size = self.cell_size
  local cx0, cy0 = floor(x0 / size), floor(y0 / size)
  local cx1, cy1 = floor(x1 / size), floor(y1 / size)
  if cx1 - cx0 > 1 or cy1 - cy0 > 1 then return true end
  local cells = self._cells
  local key = cx0 + cy0 * KEY_STRIDE + KEY_OFFSET
  if cells[key] or cells[key + (cx1 - cx0)] then return true end
  key = key + (cy1 - cy0) * KEY_STRIDE
  return (cells[key] or cells[key + (cx1 - cx0)]) ~= nil
end

-- Appends the records of one cell not stamped yet to `out`, stamping them.
local function collect_cell(cell, stamp, out, n)
  for i = 1, #cell do
    local record = cell[i]
    if record._stamp ~= stamp then
      record._stamp = stamp
      n = n + 1
      out[n] = record
    end
  end
  return n
end

---Appends to `out` (from index n + 1) every record in the cells touched by the
---rectangle from (x0, y0) to (x1, y1), once each, and returns the new count. Records come
---cell by cell in row order, and in insertion order inside a cell; callers sort what they
---return. (The far sides as given: x0 + (x1 - x0) can round below x1, and a cell edge
---between the two would be missed.)
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param out budge.HashRecord[]
---@param n integer how many entries of `out` to keep
---@return integer n
function Hash:collect_between(x0, y0, x1, y1, out, n)
  local size = self.cell_size
  local cx0, cy0 = floor(x0 / size), floor(y0 / size)
  local cx1, cy1 = floor(x1 / size), floor(y1 / size)
  local stamp = self:next_stamp()
  local all = self._all
  if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > self._n then -- fewer records than cells: walk them
    return list_touching(all, self._n, cx0, cy0, cx1, cy1, out, n)
  end
  -- LuaJIT shaping: one flat loop over the cells (as in axis_stop), each cell's records
  -- taken by collect_cell: the nested loops spawned a side trace for each shape of a
  -- rectangle (732 of 5430 traces and 24 flushes in 50 frames of bench/contacts.lua).
  local cells = self._cells
  local columns = cx1 - cx0 + 1
  for k = 0, columns * (cy1 - cy0 + 1) - 1 do
    local row = floor(k / columns)
    local cell = cells[(cx0 + (k - row * columns)) + (cy0 + row) * KEY_STRIDE + KEY_OFFSET]
    if cell then n = collect_cell(cell, stamp, out, n) end
  end
  local big = self._big
  if big[1] then return list_touching(big, #big, cx0, cy0, cx1, cy1, out, n) end
  return n
end

---Hash:collect_between for the rectangle at (x, y) of `width` and `height`.
---@param x number
---@param y number
---@param width number
---@param height number
---@param out budge.HashRecord[]
---@param n integer how many entries of `out` to keep
---@return integer n
function Hash:collect(x, y, width, height, out, n)
  return self:collect_between(x, y, x + width, y + height, out, n)
end

-- overlapping_in_cell on Lua 5.1-5.4, with comparisons: there math.min is a call into C
-- (budge.bump's nearest_compared has what the LuaJIT forms cost there).
local function overlapping_compared(cell, stamp, x0, y0, x1, y1, out, n)
  for i = 1, #cell do
    local record = cell[i]
    if record[1] < x1 and x0 < record[1] + record[3] and record[2] < y1
      and y0 < record[2] + record[4] and record._stamp ~= stamp then
      record._stamp = stamp
      n = n + 1
      out[n] = record
    end
  end
  return n
end

-- Appends the records of one cell that overlap the rectangle (x0, y0)-(x1, y1) strictly
-- and are not stamped yet to `out`, stamping them.
-- LuaJIT shaping: the overlap as one test, the min of the differences (exact: for finite
-- numbers a - b > 0 if and only if a > b, see scan_packs), not four comparisons, each a
-- side exit when it fails: budge.bump's moves (`luajit bench/world.lua --way bump_boxes`, 5 fresh runs each,
-- interleaved, 2026-12-01) 3830 -> 3016 ns per move with 10000 items, 1414 -> 1316 with
-- 1000, alone.
local function overlapping_in_cell(cell, stamp, x0, y0, x1, y1, out, n)
  for i = 1, #cell do
    local record = cell[i]
    if min(x1 - record[1], record[1] + record[3] - x0, y1 - record[2],
      record[2] + record[4] - y0) > 0 and record._stamp ~= stamp then
      record._stamp = stamp
      n = n + 1
      out[n] = record
    end
  end
  return n
end

-- Appends the records of one cell whose box overlaps or touches the closed rectangle
-- (x0, y0)-(x1, y1) and that are not stamped yet to `out`, stamping them. (Comparisons:
-- Hash:collect_touching serves Lua 5.1-5.4, see solids.lua's gather_all.)
local function touching(cell, stamp, x0, y0, x1, y1, out, n)
  for i = 1, #cell do
    local record = cell[i]
    if record[1] <= x1 and x0 <= record[1] + record[3] and record[2] <= y1
      and y0 <= record[2] + record[4] and record._stamp ~= stamp then
      record._stamp = stamp
      n = n + 1
      out[n] = record
    end
  end
  return n
end

-- (the form this interpreter takes, chosen once: not a call more per cell on Lua 5.x)
local overlapping = BRANCH_FREE and overlapping_in_cell or overlapping_compared

-- Appends to `out` (from index n + 1) the records `in_cell` keeps (overlapping or
-- touching) of those in the cells the rectangle (x0, y0)-(x1, y1) touches, once each, in
-- the order Hash:collect gives; returns the new count. With fewer records than cells, the
-- list of all records is tested instead (a record's box lies inside the box its cells were
-- chosen by, so a box the test keeps is in those cells; its two sentinels, boxes at +inf,
-- fail the test of any finite rectangle; `#` finds n + 2 there, a search on LuaJIT, only
-- in a hash of fewer records than the cells asked about).
local function collect_kept(self, x0, y0, x1, y1, out, n, in_cell)
  local size = self.cell_size
  local cx0, cy0 = floor(x0 / size), floor(y0 / size)
  local cx1, cy1 = floor(x1 / size), floor(y1 / size)
  local stamp = self:next_stamp()
  if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > self._n then
    return in_cell(self._all, stamp, x0, y0, x1, y1, out, n)
  end
  local cells = self._cells
  local columns = cx1 - cx0 + 1
  for k = 0, columns * (cy1 - cy0 + 1) - 1 do -- (one flat loop: see Hash:collect)
    local row = floor(k / columns)
    local cell = cells[(cx0 + (k - row * columns)) + (cy0 + row) * KEY_STRIDE + KEY_OFFSET]
    if cell then n = in_cell(cell, stamp, x0, y0, x1, y1, out, n) end
  end
  local big = self._big
  if big[1] then return in_cell(big, stamp, x0, y0, x1, y1, out, n) end
  return n
end

-- The cells (cx0..cx1, cy0..cy1) of a packed hash narrowed to those with a slot (only
-- they can hold anything, see regrid): their first column and row, how many columns and
-- how many cells. Comparisons on every interpreter: a NaN side leaves no cell to scan
-- (LuaJIT's math.max(NaN, a) is a).
local function slotted(self, cx0, cy0, cx1, cy1)
  if cx0 < self._gx0 then cx0 = self._gx0 end
  if cy0 < self._gy0 then cy0 = self._gy0 end
  if cx1 > self._gx1 then cx1 = self._gx1 end
  if cy1 > self._gy1 then cy1 = self._gy1 end
  local columns = cx1 - cx0 + 1
  return cx0, cy0, columns, (columns > 0 and cy1 >= cy0) and columns * (cy1 - cy0 + 1) or 0
end

-- Where the first of `count` cells from (cx0, cy0) of a packed hash has its entries in the
-- store, for the flat loops over cells (collect_packed, scan_packs) to start in it: its
-- first entry's start and its last's (last below first when the cell has no entry: 1, -5
-- when there is no cell or it has no slot). The hash's _span, _gx0, _gy0 and _gw given,
-- as the loops hold them.
-- LuaJIT shaping: worked out before the loop, the loop's first turn is an entry's, not
-- the next cell's. A loop whose first turn leaves its trace runs the trace's start again
-- from a side trace: once more per scan, where a scan of merged boxes runs 4.2 entries in
-- 1.4 cells (`luajit bench/world.lua --way merged --count 100`). Machine instructions a
-- move (`luajit bench/instructions.lua --way W --count 100 --frames 300`, 2026-12-07):
-- merged boxes 3212-3270 -> 3066-3133 (5 runs each, 3312 in a sixth), box per tile
-- 3240-3254 in 2 runs of 3 (3594 in the third, another compile).
local function first_run(span, gx0, gy0, gw, cx0, cy0, count)
  if count > 0 then
    local slot = (cy0 - gy0) * gw + (cx0 - gx0) + 1
    local first = span[2 * slot - 1]
    if first then return first, span[2 * slot] end
  end
  return 1, -5
end

-- Hash:collect_overlapping over a packed hash: the cells' entries in the store, not the
-- records (a record is a table of its own, its box in its array part: two or three
-- cache lines apart per record, where the store holds a cell's boxes side by side), and
-- no stamps written: a record met in several of the scanned cells is kept in the first of
-- them in the scan's order, (max(its first column, the scan's), max(its first row, the
-- scan's)), as consider_packed keeps a tie. (Its entries hold its own box, which lies in
-- the box its cells were worked out from: a record that overlaps the rectangle strictly
-- has an entry in every scanned cell the overlap meets with more than an edge, and that
-- cell is one.) The cells (cx0, cy0, columns, count) as slotted gives them;
-- Hash:collect_overlapping leaves a rectangle over more cells than the hash has records to
-- collect_kept, and adds the big records. One flat loop, as scan_packs (LuaJIT shaping:
-- see there).
-- Speed: budge.bump's moves (its items the world's actors, in a packed hash): see the
-- CHANGELOG's entry "Faster budge.bump moves" (interleaved fresh runs, before and after).
local function collect_packed(self, cx0, cy0, columns, count, x0, y0, x1, y1, out, n)
  local size = self.cell_size
  local store, span = self._store, self._span
  local gx0, gy0, gw = self._gx0, self._gy0, self._gw
  local k, cx, cy = 0, cx0, cy0
  local base, last = first_run(span, gx0, gy0, gw, cx0, cy0, count)
  while true do
    if base > last then -- the next cell
      k = k + 1
      if not (k < count) then break end -- luacheck: ignore (not >=: a NaN count ends it too)
      local row = floor(k / columns)
      cx, cy = cx0 + (k - row * columns), cy0 + row
      local slot = (cy - gy0) * gw + (cx - gx0) + 1
      local first = span[2 * slot - 1]
      if first then base, last = first, span[2 * slot] end
    else
      local x, y = store[base + 1], store[base + 2]
      if min(x1 - x, store[base + 3] - x0, y1 - y, store[base + 4] - y0) > 0
        and max(floor(x / size), cx0) == cx and max(floor(y / size), cy0) == cy then
        n = n + 1
        out[n] = store[base + 6]
      end
      base = base + 6
    end
  end
  return n
end

-- collect_packed on Lua 5.1-5.4: comparisons, and floor only for an entry that overlaps
-- (there math.min, math.max and math.floor are calls into C). The same records, in the
-- same order. Lua 5.4, budge.bump with a box per tile, 10000 items (`lua5.4
-- bench/instructions.lua --way bump_boxes --count 10000 --frames 5 --lua lua5.4`,
-- 2026-12-05): 63940 instructions per move with the records' scan, 90229 with
-- collect_packed's min and max, 75564 with this (and 71326 with find_entry).
local function collect_packed_compared(self, cx0, cy0, columns, count, x0, y0, x1, y1, out, n)
  local size = self.cell_size
  local store, span = self._store, self._span
  local gx0, gy0, gw = self._gx0, self._gy0, self._gw
  for k = 0, count - 1 do
    local row = floor(k / columns)
    local cx, cy = cx0 + (k - row * columns), cy0 + row
    local slot = (cy - gy0) * gw + (cx - gx0) + 1
    local first = span[2 * slot - 1]
    if first then
      for base = first, span[2 * slot], 6 do
        local x, y = store[base + 1], store[base + 2]
        if x < x1 and x0 < store[base + 3] and y < y1 and y0 < store[base + 4] then
          local fx, fy = floor(x / size), floor(y / size)
          if (fx > cx0 and fx or cx0) == cx and (fy > cy0 and fy or cy0) == cy then
            n = n + 1
            out[n] = store[base + 6]
          end
        end
      end
    end
  end
  return n
end

local packed_collect = BRANCH_FREE and collect_packed or collect_packed_compared

---Appends to `out` (from index n + 1) every record whose box (its x, y, width and
---height) overlaps the rectangle from (x0, y0) to (x1, y1) strictly, once each, and
---returns the new count; in the order Hash:collect gives. (budge.bump's moves: the
---overlap test while walking the cells, instead of a second pass over everything collect
---finds.) The far sides as given: a leg's rectangle ends at the goal's far side, and x0
---+ (x1 - x0) can round below it.
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param out budge.HashRecord[]
---@param n integer how many entries of `out` to keep
---@return integer n
function Hash:collect_overlapping(x0, y0, x1, y1, out, n)
  if self._packed then
    local size = self.cell_size
    local cx0, cy0 = floor(x0 / size), floor(y0 / size)
    local cx1, cy1 = floor(x1 / size), floor(y1 / size)
    if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) <= self._n then -- (else collect_kept's: see there)
      local columns, count
      cx0, cy0, columns, count = slotted(self, cx0, cy0, cx1, cy1)
      n = packed_collect(self, cx0, cy0, columns, count, x0, y0, x1, y1, out, n)
      local big = self._big
      if big[1] then return overlapping(big, self:next_stamp(), x0, y0, x1, y1, out, n) end
      return n
    end
  end
  return collect_kept(self, x0, y0, x1, y1, out, n, overlapping)
end

---Appends to `out` (from index n + 1) every record whose box overlaps or touches the
---closed rectangle from (x0, y0) to (x1, y1), once each, and returns the new count; in
---the order Hash:collect gives. (A filtered move's candidates, solids.lua: the test while
---walking the cells, instead of a second pass over everything collect finds.)
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param out budge.HashRecord[]
---@param n integer how many entries of `out` to keep
---@return integer n
function Hash:collect_touching(x0, y0, x1, y1, out, n)
  return collect_kept(self, x0, y0, x1, y1, out, n, touching)
end

-- Where the box (the probe's values, given: see sweep.AxisProbe) stops against a face (a
-- low face moving forward, a high one moving back), as sweep.stop_forward/backward decide,
-- when that is no worse than the best stop so far, `best`; else nil.
local function stop_at(face, oneway, best, forward, pos, edge, reach, size, blocks_oneway)
  local stop
  if forward then
    stop = stop_forward(face, pos, edge, reach, size, oneway, blocks_oneway)
  else
    stop = stop_backward(face, pos, edge, reach, oneway, blocks_oneway)
  end
  if stop == nil then return nil end
  if best ~= nil and (forward and stop > best or not forward and stop < best) then
    return nil
  end
  return stop
end

-- One record that spans the probe's path across: where it stops the probe, if it does,
-- and whether that is the best stop so far.
-- LuaJIT shaping: probe fields are read where they are used, not hoisted into locals:
-- fewer values live across the loop's exits keeps LuaJIT from aborting the trace
-- ("register coalescing too complex"); moves near hashed solids went 405 -> 270 ns
-- (commit bc30993, make bench-world). stop_at's work written out: the scan over records
-- is the one Lua 5.1-5.4 use (world.lua), and there the call per candidate made moves
-- among boxes 3.4% slower (`lua5.4 bench/world.lua --way boxes --count 1000 --frames 60`,
-- 5 fresh runs, 2026-12-01: 4345 ns against 4200).
local function consider(probe, record, low, length)
  local stop
  if probe.forward then
    stop = stop_forward(low, probe.pos, probe.edge, probe.reach, probe.size, record.oneway,
      probe.blocks_oneway)
  else
    stop = stop_backward(low + length, probe.pos, probe.edge, probe.reach, record.oneway,
      probe.blocks_oneway)
  end
  if stop == nil or record.removed then return end
  local best = probe.best
  if best ~= nil and (probe.forward and stop > best or not probe.forward and stop < best) then
    return
  end
  local touched = probe.touched
  if stop ~= best then probe.best = stop; touched = 0 end
  touched = touched + 1
  local payload = probe.payload
  probe.touch[touched], probe.touch_id[touched] = payload and record[payload] or record,
    record[6]
  probe.touch_left[touched], probe.touch_top[touched] = record[1], record[2]
  probe.touched = touched
end

-- The probe over records 1 to n of `list` (a cell's, the big ones, or all of them and
-- the two sentinels after them).
local function scan_cell(list, n, stamp, probe)
  for i = 1, n do
    local record = list[i]
    if record._stamp ~= stamp then
      record._stamp = stamp
      if probe.is_x then
        if record[2] < probe.cross_end and probe.cross < record[2] + record[4] then
          consider(probe, record, record[1], record[3])
        end
      elseif record[1] < probe.cross_end and probe.cross < record[1] + record[3] then
        consider(probe, record, record[2], record[4])
      end
    end
  end
end

-- consider for the packed box at `base` of a pack, in the cell (cx, cy), whose face on
-- the axis is at `face` (its low face moving forward, its high one moving back). A record
-- in several of the scanned cells is met in each: a meeting after the first can only tie
-- (same box, same stop), and on a tie it counts only in the record's first cell in the
-- scan's order, (max(its first column, the scan's), max(its first row, the scan's)), so
-- that the first meeting keeps its place, as the stamps do in scan_cell, at a constant
-- cost (a search of the touch list would cost its length at every tie). The scan's first
-- column and row are scan_cx0 and scan_cy0, its hash's cell size `cell`; the moving box's
-- values (sweep.AxisProbe's fields of those names) from `forward` on.
local function consider_packed(probe, pack, base, face, cx, cy, scan_cx0, scan_cy0, cell,
                               forward, pos, edge, reach, size, blocks_oneway)
  local flag = pack[base + 5]
  local stop = stop_at(face, flag < 0, probe.best, forward, pos, edge, reach, size,
    blocks_oneway)
  if stop == nil then return end -- (a solid removed during the move: no entry passes the
  -- scan's test, solids.retire emptied them; the record is not read here)
  local touched = probe.touched
  if stop ~= probe.best then
    probe.best = stop
    touched = 0
  else
    local first_cx, first_cy = floor(pack[base + 1] / cell), floor(pack[base + 2] / cell)
    if first_cx < scan_cx0 then first_cx = scan_cx0 end
    if first_cy < scan_cy0 then first_cy = scan_cy0 end
    if cx ~= first_cx or cy ~= first_cy then return end -- met in an earlier cell
  end
  touched = touched + 1
  probe.touch[touched], probe.touch_id[touched] = pack[base + 6], abs(flag)
  probe.touch_left[touched], probe.touch_top[touched] = pack[base + 1], pack[base + 2]
  probe.touched = touched
end

-- scan_cell over the packed boxes of the cells the probe's rectangle touches: `count`
-- cells, `columns` to a row, from (cx0, cy0), row by row.
-- face_slot and cross_slot are the slots of the face on the axis and of the low side
-- across it (1: x, 2: y, 3: right, 4: bottom); `sign` is 1 moving forward and -1
-- moving back, signed_reach the reach times sign, signed_pos the low end of the faces that
-- can stop the box times sign, and cross, cross_end the box's sides across the axis, so
-- that one test on the face times the sign keeps what stop_forward or
-- stop_backward can stop at: a face at or short of the reach, at or ahead of the box's
-- start (a superset: stop_at decides). Across, the strict overlap, exactly: for finite
-- numbers a - b > 0 if and only if a > b (a difference rounds to 0 only when they are
-- equal, with IEEE gradual underflow, which Lua and LuaJIT run with unless native code
-- in the process turns it off); the face test's min + TINY is above 0 whenever the min
-- is at least 0 (and for a negative subnormal min too: still a superset).
-- LuaJIT shaping, both measured on `luajit bench/world.lua --way boxes --count 1000`
-- (5 fresh runs each, interleaved, 2026-12-01):
-- * one loop over the entries of all the cells, not a loop over cells calling a loop over
--   entries: every exit from the inner loop ran a side trace back into the cell loop and
--   into the inner loop's trace again (about 3 times a move), and
-- * one test, the min of the differences, not five comparisons: each comparison an entry
--   failed was a side exit and a jump back to the start of the loop's trace.
--   Box per tile 1160-1276 ns per move before, 873-929 after.
-- The loop ends by a break, not a return from inside it: with the return, 3 runs in 10
-- took 1406-1427 ns instead of 860-980. In those, LuaJIT had compiled the loop as a trace
-- that returns instead of looping ("hash.lua:506 return" in `luajit -jv`), every trace
-- reaching the loop then aborted ("inner loop in root trace"), and the functions of the
-- move were blacklisted one after the other. With the break: 0 in 10.
local TINY = 2 ^ -1022
local function scan_packs(self, probe, cx0, cy0, columns, count, face_slot, cross_slot, sign,
                          signed_reach, signed_pos, cross, cross_end, forward, pos, edge,
                          reach, size, blocks_oneway)
  local store, span, cell = self._store, self._span, self.cell_size
  local gx0, gy0, gw = self._gx0, self._gy0, self._gw
  local k, cx, cy = 0, cx0, cy0
  local base, last = first_run(span, gx0, gy0, gw, cx0, cy0, count)
  while true do
    if base > last then -- the next cell
      k = k + 1
      if not (k < count) then break end -- luacheck: ignore (not >=: a NaN count ends it too)
      local row = floor(k / columns)
      cx, cy = cx0 + (k - row * columns), cy0 + row
      local slot = (cy - gy0) * gw + (cx - gx0) + 1 -- (the slot insert uses)
      local first = span[2 * slot - 1]
      if first then base, last = first, span[2 * slot] end
    else
      local face = store[base + face_slot]
      local signed = sign * face
      if min(min(signed_reach - signed, signed - signed_pos) + TINY,
        cross_end - store[base + cross_slot],
        store[base + cross_slot + 2] - cross) > 0 then
        consider_packed(probe, store, base, face, cx, cy, cx0, cy0, cell, forward, pos, edge,
          reach, size, blocks_oneway)
      end
      base = base + 6
    end
  end
end

-- scan_packs on Lua 5.1-5.4, with comparisons: there math.min is a call into C. The
-- same entries pass: the faces from the box's start to the reach (the superset stop_at
-- decides on), and the strict overlap across. `lua5.4 bench/world.lua --way boxes
-- --count 1000 --frames 60`, 5 fresh runs each, interleaved, 2026-12-02: 3784 ns per move
-- with the records' scan (scan_cell: unpacked, as Lua 5.x had it), 3470 with this; merged
-- boxes 3453 -> 3301.
local function scan_packs_compared(self, probe, cx0, cy0, columns, count, face_slot,
                                   cross_slot, cross, cross_end, forward, pos, edge, reach,
                                   size, blocks_oneway)
  local store, span, cell = self._store, self._span, self.cell_size
  local gx0, gy0, gw = self._gx0, self._gy0, self._gw
  local low, high = pos, reach -- (forward; back, from the reach to the edge)
  if not forward then low, high = reach, edge end
  for k = 0, count - 1 do
    local row = floor(k / columns)
    local cx, cy = cx0 + (k - row * columns), cy0 + row
    local slot = (cy - gy0) * gw + (cx - gx0) + 1
    local first = span[2 * slot - 1]
    if first then
      for base = first, span[2 * slot], 6 do
        local face = store[base + face_slot]
        if face >= low and face <= high and store[base + cross_slot] < cross_end
          and store[base + cross_slot + 2] > cross then
          consider_packed(probe, store, base, face, cx, cy, cx0, cy0, cell, forward, pos,
            edge, reach, size, blocks_oneway)
        end
      end
    end
  end
end

-- The probe over a packed hash's cells cx0..cx1, cy0..cy1 (scan_packs on LuaJIT,
-- scan_packs_compared on Lua 5.1-5.4), the moving box's values given (sweep.AxisProbe's
-- fields of those names).
-- Speed: the scans' values as arguments, not written into the probe for the scan to read
-- back (with move.lua's lean_solids_phase, which hands them over the same way): `luajit
-- bench/instructions.lua --way W --count 100 --frames 300` counted 3315-3360 machine
-- instructions a move of merged boxes instead of 3492-3519 (3 runs each), 3472-3478 a
-- move of a box per tile instead of 3642-3649 (2 runs each); `luajit bench/world.lua
-- --way W --count 100`, fresh runs interleaved, medians in ns a move: merged 332 -> 323
-- (9 runs), box per tile 355 -> 326 (7 runs), 2026-12-07 (AMD EPYC). No trace aborts in
-- either way's moves (`luajit -jv`, 200 frames), as before: the scan's loop reads these
-- values and never changes them, so no exit has to write them back.
local function packed_scan(self, probe, is_x, forward, pos, edge, reach, size, blocks_oneway,
                           cross, cross_end, cx0, cy0, cx1, cy1)
  local face_slot, cross_slot
  if is_x then face_slot, cross_slot = forward and 1 or 3, 2
  else face_slot, cross_slot = forward and 2 or 4, 1 end
  local columns, count
  cx0, cy0, columns, count = slotted(self, cx0, cy0, cx1, cy1)
  if BRANCH_FREE then
    local sign = forward and 1 or -1
    scan_packs(self, probe, cx0, cy0, columns, count, face_slot, cross_slot, sign,
      sign * reach, forward and pos or -edge, cross, cross_end, forward, pos, edge, reach,
      size, blocks_oneway)
  else
    scan_packs_compared(self, probe, cx0, cy0, columns, count, face_slot, cross_slot, cross,
      cross_end, forward, pos, edge, reach, size, blocks_oneway)
  end
end

---Hash:axis_stop with the box's values given rather than read from the probe (see
---sweep.AxisProbe; blocks_oneway is `not is_x and forward`), for move.lua's
---lean_solids_phase: the probe holds only its outputs (best nil and touched 0 when it
---starts), unless the hash is small (SMALL records or fewer), has fewer records than the
---rectangle has cells, has big records or is not packed: then the values are written into
---it and Hash:axis_stop runs. The same outcomes.
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param probe budge.AxisProbe
---@param is_x boolean
---@param forward boolean
---@param pos number
---@param edge number
---@param reach number
---@param size number
---@param cross number
---@param cross_end number
function Hash:lean_stop(x0, y0, x1, y1, probe, is_x, forward, pos, edge, reach, size, cross,
                        cross_end)
  local cell = self.cell_size
  local cx0, cy0 = floor(x0 / cell), floor(y0 / cell)
  local cx1, cy1 = floor(x1 / cell), floor(y1 / cell)
  local n = self._n
  if n <= SMALL or (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > n or self._big[1]
    or not self._packed then
    probe.is_x, probe.forward, probe.pos, probe.edge, probe.reach = is_x, forward, pos, edge,
      reach
    probe.size, probe.cross, probe.cross_end = size, cross, cross_end
    probe.blocks_oneway = not is_x and forward
    return Hash.axis_stop(self, x0, y0, x1, y1, probe)
  end
  packed_scan(self, probe, is_x, forward, pos, edge, reach, size, not is_x and forward, cross,
    cross_end, cx0, cy0, cx1, cy1)
end

---Runs the probe over the records (each with its box's x, y, width, height copied in,
---and `item` what the filter is given) in the cells the rectangle touches: where the
---box stops, as sweep.stop_forward/backward decide, lands in probe.best, and the records
---that stop it there in probe.touch[1..probe.touched]. (No filter is asked: a move with
---one gathers its candidates instead.) The rectangle from (x0, y0) to (x1, y1), its far
---sides as given (see collect_between).
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param probe budge.AxisProbe
function Hash:axis_stop(x0, y0, x1, y1, probe)
  probe.payload = self._payload -- (what its touch list holds: see hash.new)
  -- (cells_of and next_stamp written out: one call less per move on Lua 5.4)
  local size = self.cell_size
  local cx0, cy0 = floor(x0 / size), floor(y0 / size)
  local cx1, cy1 = floor(x1 / size), floor(y1 / size)
  local stamp = self._stamp + 1
  self._stamp = stamp
  local cells = self._cells
  local columns = cx1 - cx0 + 1
  local count = columns * (cy1 - cy0 + 1)
  -- only a few records, or fewer records than cells: scan them all (bounded work; and
  -- LuaJIT shaping: a world of a few moving platforms takes one path, not two, and tests
  -- its count of records first, the same at every move, so that no test of the count of
  -- cells, which differs from move to move, is compiled for it)
  if self._n <= SMALL or count > self._n then
    scan_cell(self._all, self._n + PAD, stamp, probe)
    return
  end
  if self._packed then
    packed_scan(self, probe, probe.is_x, probe.forward, probe.pos, probe.edge, probe.reach,
      probe.size, probe.blocks_oneway, probe.cross, probe.cross_end, cx0, cy0, cx1, cy1)
  else -- (one flat loop over the cells, as in collect; the key is the one insert uses)
    for k = 0, count - 1 do
      local row = floor(k / columns)
      local cell = cells[(cx0 + (k - row * columns)) + (cy0 + row) * KEY_STRIDE + KEY_OFFSET]
      if cell then scan_cell(cell, #cell, stamp, probe) end
    end
  end
  local big = self._big
  if big[1] then scan_cell(big, #big, stamp, probe) end
end

-- The scans as functions of the module too, for the world's moves to call without the
-- method lookup: a key missing from the hash's own table is a search of its hash part,
-- then the metatable's, in every compiled move (LuaJIT: an HREF, not an HREFK).
hash.axis_stop, hash.lean_stop = Hash.axis_stop, Hash.lean_stop

return hash
