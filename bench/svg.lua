-- bench/svg.lua: a small SVG writer for the bench charts (no dependency).
local svg = {}
svg.__index = svg

local format, concat = string.format, table.concat

local function escape(text)
  return (tostring(text):gsub("&", "&amp;"):gsub("<", "&lt;"):gsub(">", "&gt;"))
end

local function attributes(style)
  local parts = {}
  local keys = {}
  for key in pairs(style or {}) do keys[#keys + 1] = key end
  table.sort(keys) -- stable output: the same chart gives the same file
  for _, key in ipairs(keys) do
    parts[#parts + 1] = format('%s="%s"', key:gsub("_", "-"), escape(style[key]))
  end
  return concat(parts, " ")
end

---A new drawing of `width` x `height` px.
function svg.new(width, height)
  local self = setmetatable({width = width, height = height, parts = {}}, svg)
  self:add(format('<rect x="0" y="0" width="%d" height="%d" fill="white"/>', width, height))
  return self
end

function svg:add(text) self.parts[#self.parts + 1] = text end

function svg:line(x1, y1, x2, y2, style)
  self:add(format('<line x1="%.2f" y1="%.2f" x2="%.2f" y2="%.2f" %s/>', x1, y1, x2, y2,
    attributes(style)))
end

function svg:polyline(points, style)
  local coords = {}
  for i = 1, #points do coords[i] = format("%.2f,%.2f", points[i][1], points[i][2]) end
  self:add(format('<polyline points="%s" fill="none" %s/>', concat(coords, " "),
    attributes(style)))
end

function svg:circle(x, y, r, style)
  self:add(format('<circle cx="%.2f" cy="%.2f" r="%.2f" %s/>', x, y, r, attributes(style)))
end

function svg:rect(x, y, width, height, style)
  self:add(format('<rect x="%.2f" y="%.2f" width="%.2f" height="%.2f" %s/>', x, y, width, height,
    attributes(style)))
end

function svg:text(x, y, text, style)
  style = style or {}
  style.font_family = style.font_family or "DejaVu Sans, Arial, sans-serif"
  style.font_size = style.font_size or 13
  self:add(format('<text x="%.2f" y="%.2f" %s>%s</text>', x, y, attributes(style), escape(text)))
end

function svg:render()
  return format('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
    .. 'viewBox="0 0 %d %d">\n%s\n</svg>\n', self.width, self.height, self.width, self.height,
    concat(self.parts, "\n"))
end

function svg:write(path)
  local file = assert(io.open(path, "w"))
  file:write(self:render())
  file:close()
end

---A plot area inside a drawing: maps data to pixels on linear or log10 axes and draws
---the frame, ticks and labels. `axes = {x = {min, max, log, label, ticks}, y = {...}}`.
function svg:plot(left, top, width, height, axes)
  local plot = {left = left, top = top, width = width, height = height, axes = axes}
  local function project(axis, value, size)
    local lo, hi, v = axis.min, axis.max, value
    if axis.log then lo, hi, v = math.log(lo, 10), math.log(hi, 10), math.log(value, 10) end
    return (v - lo) / (hi - lo) * size
  end
  function plot.x(value) return left + project(axes.x, value, width) end
  function plot.y(value) return top + height - project(axes.y, value, height) end
  self:rect(left, top, width, height, {fill = "none", stroke = "#444", stroke_width = 1})
  for _, tick in ipairs(axes.x.ticks) do
    local x = plot.x(tick)
    self:line(x, top, x, top + height, {stroke = "#ddd", stroke_width = 1})
    self:text(x, top + height + 18, axes.x.format and axes.x.format(tick) or tick,
      {text_anchor = "middle", font_size = 12})
  end
  for _, tick in ipairs(axes.y.ticks) do
    local y = plot.y(tick)
    self:line(left, y, left + width, y, {stroke = "#ddd", stroke_width = 1})
    self:text(left - 8, y + 4, axes.y.format and axes.y.format(tick) or tick,
      {text_anchor = "end", font_size = 12})
  end
  self:text(left + width / 2, top + height + 40, axes.x.label,
    {text_anchor = "middle", font_size = 14})
  self:add(format('<text x="%.2f" y="%.2f" transform="rotate(-90 %.2f %.2f)" text-anchor="middle" '
    .. 'font-family="DejaVu Sans, Arial, sans-serif" font-size="14">%s</text>',
    left - 48, top + height / 2, left - 48, top + height / 2, escape(axes.y.label)))
  return plot
end

return svg
