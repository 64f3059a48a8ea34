-- The LuaLS annotations stay complete (no LuaLS package is reachable here, so this spec
-- is the checker): every function of a src/budge module that is not local carries
-- ---@param for each parameter and ---@return when it returns a value, and every field
-- budge.new_world puts into a world is declared on budge.World.
local files = require("spec.support.files")

local module_files = files.module_files

local function lines_of(text)
  local lines = {}
  for line in (text .. "\n"):gmatch("([^\n]*)\n") do lines[#lines + 1] = line end
  return lines
end

-- The non-local functions of a file: name, parameters, the doc block above, and whether
-- the body returns a value (a `return` followed by something, in the body's own lines).
local function public_functions(path)
  local lines = lines_of(files.read(path))
  local found = {}
  for i, line in ipairs(lines) do
    local name, params = line:match("^function ([%w_%.:]+)%(([^)]*)%)")
    if name then
      local doc = {}
      local j = i - 1
      while j >= 1 and lines[j]:match("^%-%-%-") do
        table.insert(doc, 1, lines[j])
        j = j - 1
      end
      local returns = false
      local k = i + 1
      while k <= #lines and lines[k] ~= "end" do
        local code = lines[k]:gsub("%-%-.*$", "")
        local value = code:match("^%s*return%s+(%S+)") or code:match("[^%w_]return%s+(%S+)")
        if value and value ~= "end" then returns = true end
        k = k + 1
      end
      if line:match("%)%s*return%s+%S") then returns = true end -- a one-line body
      local names = {}
      for param in params:gmatch("[%w_%.]+") do
        if param ~= "..." then names[#names + 1] = param end
      end
      found[#found + 1] = {name = name, line = i, params = names, doc = table.concat(doc, "\n"),
        returns = returns}
    end
  end
  return found
end

-- What a file's non-local functions lack: one line each.
local function problems(path)
  local missing = {}
  local functions = public_functions(path)
  for _, fn in ipairs(functions) do
    local where = ("%s:%d %s"):format(path, fn.line, fn.name)
    if fn.doc == "" then missing[#missing + 1] = where .. ": no doc comment" end
    for _, param in ipairs(fn.params) do
      if not fn.doc:find("%-%-%-@param " .. param:gsub("_", "%%_") .. "%??%s") then
        missing[#missing + 1] = where .. ": no ---@param " .. param
      end
    end
    if fn.returns and not fn.doc:find("---@return", 1, true) then
      missing[#missing + 1] = where .. ": no ---@return"
    end
  end
  return missing, #functions
end

describe("the annotations", function()
  it("declare every parameter and return value of every non-local function in src/budge", function()
    local missing, checked = {}, 0
    for _, path in ipairs(module_files()) do
      local found, count = problems(path)
      checked = checked + count
      for _, line in ipairs(found) do missing[#missing + 1] = line end
    end
    assert.is_true(checked > 60, "found only " .. checked .. " functions: is the parser right?")
    assert.same({}, missing)
  end)

  it("declare on budge.World every field a new world has", function()
    local budge = require("budge")
    local text = files.read("src/budge/world.lua")
    local block = text:match("%-%-%-@class budge%.World\n(.-)\nlocal World")
    assert.is_string(block)
    local declared = {}
    for field in block:gmatch("%-%-%-@field package ([%w_]+)") do declared[field] = true end
    for field in block:gmatch("%-%-%-@field ([%w_]+)") do declared[field] = true end
    local undeclared = {}
    for field in pairs(budge.new_world()) do
      if not declared[field] then undeclared[#undeclared + 1] = field end
    end
    table.sort(undeclared)
    assert.same({}, undeclared)
  end)

  it("would catch an undeclared parameter, a missing return and a bare function", function()
    local path = os.tmpname()
    local file = assert(io.open(path, "w"))
    file:write("---Adds.\n---@param a number\nfunction m.add(a, b)\n  return a + b\nend\n\n"
      .. "function m:bare(x_y) end\n")
    file:close()
    local missing = problems(path)
    os.remove(path)
    for i, line in ipairs(missing) do missing[i] = line:gsub("^.-:", "") end
    assert.same({"3 m.add: no ---@param b", "3 m.add: no ---@return",
      "7 m:bare: no doc comment", "7 m:bare: no ---@param x_y"}, missing)
  end)
end)
