-- bench/chart.lua: draws the charts from bench/results/*.csv into docs/.
--   docs/speed-vs-accuracy.svg  ns per move (log) against accuracy, per method and interpreter
--   docs/envelopes.svg          largest safe speed against wall thickness, measured and analytic
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local svg = require("bench.svg")
local budge = require("budge")

local function parse_line(line)
  local fields, position = {}, 1
  while position <= #line + 1 do
    if line:sub(position, position) == '"' then
      local close = line:find('"', position + 1, true)
      fields[#fields + 1] = line:sub(position + 1, close - 1)
      position = close + 2
    else
      local comma = line:find(",", position, true) or #line + 1
      fields[#fields + 1] = line:sub(position, comma - 1)
      position = comma + 1
    end
  end
  return fields
end

local function read_csv(path)
  local file = io.open(path, "r")
  if not file then return nil end
  local header, rows = nil, {}
  for line in file:lines() do
    local fields = parse_line(line)
    if not header then
      header = fields
    else
      local row = {}
      for i, name in ipairs(header) do row[name] = tonumber(fields[i]) or fields[i] end
      rows[#rows + 1] = row
    end
  end
  file:close()
  return rows
end

-- one colour per rung of the ladder, cheapest first (budge.METHODS' order)
local PALETTE = {"#d62728", "#ff7f0e", "#9467bd", "#8c564b", "#2ca02c", "#1f77b4", "#17becf"}
local METHOD_ORDER = budge.METHODS
local COLORS = {}
for i, method in ipairs(METHOD_ORDER) do COLORS[method] = PALETTE[i] end

-- speed against accuracy -------------------------------------------------------------
local series = {}
for _, tag in ipairs({"luajit", "lua5.4", "lua5.1", "lua5.2", "lua5.3"}) do
  local rows = read_csv("bench/results/" .. tag .. ".csv")
  if rows then series[#series + 1] = {tag = tag, rows = rows} end
end
assert(#series > 0, "no bench/results/<interpreter>.csv: run bench/run.lua first")

local low, high = math.huge, 0
for _, s in ipairs(series) do
  for _, row in ipairs(s.rows) do
    low = math.min(low, row.ns_per_move)
    high = math.max(high, row.ns_per_move)
  end
end
local x_min = 10 ^ math.floor(math.log(low * 0.7, 10))
local x_max = 10 ^ math.ceil(math.log(high * 1.4, 10))
local x_ticks = {}
local decade = x_min
while decade <= x_max + 1e-9 do
  for _, m in ipairs({1, 2, 5}) do
    if decade * m <= x_max + 1e-9 then x_ticks[#x_ticks + 1] = decade * m end
  end
  decade = decade * 10
end

local drawing = svg.new(900, 560)
drawing:text(450, 30, "budge: speed against accuracy, one point per method and interpreter",
  {text_anchor = "middle", font_size = 17, font_weight = "bold"})
local plot = drawing:plot(90, 60, 560, 420, {
  x = {min = x_min, max = x_max, log = true, ticks = x_ticks,
    label = "cost: ns per move on the world bench scene (log scale; left is faster)",
    format = function(v) return ("%g"):format(v) end},
  y = {min = 40, max = 100, ticks = {40, 50, 60, 70, 80, 90, 100},
    label = "accuracy: % of catalogue cases right",
    format = function(v) return v .. "%" end},
})
local MARKERS = {luajit = "circle", ["lua5.4"] = "square"}
-- Labels are placed after all markers, each at the first free spot near its point
-- (never over another label or marker), with a leader line when it had to move away.
local taken, labels = {}, {}
local function free(x0, y0, x1, y1)
  for _, r in ipairs(taken) do
    if x0 < r[3] and r[1] < x1 and y0 < r[4] and r[2] < y1 then return false end
  end
  return true
end
for _, s in ipairs(series) do
  for _, row in ipairs(s.rows) do
    local x, y = plot.x(row.ns_per_move), plot.y(row.accuracy_percent)
    local color = COLORS[row.method] or "#333"
    if (MARKERS[s.tag] or "square") == "circle" then
      drawing:circle(x, y, 7, {fill = color, stroke = "black", stroke_width = 1})
    else
      drawing:rect(x - 6, y - 6, 12, 12, {fill = color, stroke = "black", stroke_width = 1})
    end
    taken[#taken + 1] = {x - 7, y - 7, x + 7, y + 7}
    labels[#labels + 1] = {x = x, y = y, text = row.method, color = color}
  end
end
local OFFSETS = {{10, -8}, {10, 14}, {-10, -8}, {-10, 14}}
for distance = 1, 8 do
  OFFSETS[#OFFSETS + 1] = {10, -8 - 15 * distance}
  OFFSETS[#OFFSETS + 1] = {10, 14 + 15 * distance}
end
for _, label in ipairs(labels) do
  local width = 7 * #label.text
  for i, offset in ipairs(OFFSETS) do
    local left = offset[1] > 0 and label.x + offset[1] or label.x + offset[1] - width
    local base = label.y + offset[2]
    if free(left, base - 11, left + width, base + 3) or i == #OFFSETS then
      taken[#taken + 1] = {left, base - 11, left + width, base + 3}
      if i > 4 then
        drawing:line(label.x, label.y, left, base - 4, {stroke = label.color, stroke_width = 1})
      end
      drawing:text(left, base, label.text, {font_size = 12, fill = label.color})
      break
    end
  end
end
-- legend
local legend_x, legend_y = 675, 70
drawing:text(legend_x, legend_y, "method", {font_weight = "bold"})
local line = 1
for _, method in ipairs(METHOD_ORDER) do
  local present = false
  for _, s in ipairs(series) do
    for _, row in ipairs(s.rows) do if row.method == method then present = true end end
  end
  if present then
    drawing:rect(legend_x, legend_y + line * 20 - 10, 12, 12, {fill = COLORS[method]})
    drawing:text(legend_x + 20, legend_y + line * 20, method)
    line = line + 1
  end
end
line = line + 1
drawing:text(legend_x, legend_y + line * 20, "interpreter", {font_weight = "bold"})
for _, s in ipairs(series) do
  line = line + 1
  local y = legend_y + line * 20 - 4
  if (MARKERS[s.tag] or "square") == "circle" then
    drawing:circle(legend_x + 6, y, 6, {fill = "#bbb", stroke = "black"})
  else
    drawing:rect(legend_x, y - 6, 12, 12, {fill = "#bbb", stroke = "black"})
  end
  drawing:text(legend_x + 20, y + 4, s.rows[1].interpreter)
end
drawing:text(legend_x, 470, ("%d cases per method"):format(series[1].rows[1].cases),
  {font_size = 12})
drawing:text(legend_x, 488, "machine: " .. (series[1].rows[1].machine or "?"), {font_size = 11})
drawing:write("docs/speed-vs-accuracy.svg")
print("wrote docs/speed-vs-accuracy.svg")

-- envelopes --------------------------------------------------------------------------
local envelopes = assert(read_csv("bench/results/envelopes.csv"), "no envelopes.csv")
local by_method, order = {}, {}
for _, row in ipairs(envelopes) do
  if not by_method[row.method] then by_method[row.method] = {}; order[#order + 1] = row.method end
  local list = by_method[row.method]
  list[#list + 1] = row
end
local chart = svg.new(900, 560)
chart:text(450, 30, "Where each discrete method fails: largest safe speed, 12 px mover",
  {text_anchor = "middle", font_size = 17, font_weight = "bold"})
local area = chart:plot(90, 60, 560, 420, {
  x = {min = 1, max = 64, log = true, ticks = {1, 2, 4, 8, 16, 32, 64},
    label = "wall thickness, px (log scale)"},
  y = {min = 0.25, max = 64, log = true, ticks = {0.25, 0.5, 1, 2, 4, 8, 16, 32, 64},
    label = "largest speed still resolved correctly, px per step (log)",
    format = function(v) return ("%g"):format(v) end},
})
for i, method in ipairs(order) do
  local rows = by_method[method]
  local color = COLORS[method] or "#333"
  local points = {}
  for _, row in ipairs(rows) do points[#points + 1] = {area.x(row.thickness), area.y(row.analytic)} end
  chart:polyline(points, {stroke = color, stroke_width = 2, stroke_dasharray = "6 4"})
  -- a method whose dots a later one covers exactly is drawn larger, so both show
  local covered = false
  for j = i + 1, #order do
    local same = true
    for k, row in ipairs(by_method[order[j]]) do
      if row.measured ~= rows[k].measured then same = false end
    end
    covered = covered or same
  end
  for _, row in ipairs(rows) do
    chart:circle(area.x(row.thickness), area.y(math.max(row.measured, 0.25)), covered and 9 or 5,
      {fill = color, stroke = "black", stroke_width = 1})
  end
end
local ly = 70
chart:text(675, ly, "measured (dots) and", {font_weight = "bold"})
chart:text(675, ly + 18, "analytic (dashed)", {font_weight = "bold"})
local FORMULAS = {seed = "seed: T/2 (from right/below)", wall_type = "wall_type: < (S+T)/2",
  min_axis = "min_axis: < (S+T)/2", fat_cross = "fat_cross: 3/8 T (side hits)"}
for i, method in ipairs(order) do
  local y = ly + 24 + i * 22
  chart:line(675, y - 4, 700, y - 4, {stroke = COLORS[method], stroke_width = 2,
    stroke_dasharray = "6 4"})
  chart:circle(687, y - 4, 4, {fill = COLORS[method], stroke = "black"})
  chart:text(708, y, FORMULAS[method] or method, {font_size = 12})
end
chart:text(675, ly + 24 + (#order + 2) * 22, "S = mover size (12), T = thickness", {font_size = 12})
chart:text(675, ly + 24 + (#order + 3) * 22, "big dots: hidden under another", {font_size = 12})
chart:text(675, ly + 24 + (#order + 4) * 22, "axis_sweep, swept: no limit", {font_size = 12})
chart:write("docs/envelopes.svg")
print("wrote docs/envelopes.svg")
