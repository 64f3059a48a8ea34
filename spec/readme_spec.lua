-- The README's examples must print what the README says they print.
local files = require("spec.support.files")

local function check_example(heading)
  local readme = files.read("README.md")
  local code = readme:match(heading .. "%s+[^`]*```lua\n(.-)```")
  assert.is_string(code)
  local expected = {}
  for line in code:gmatch("[^\n]+") do
    local shown = line:match("^print%(.*%-%->%s*(.-)%s*$")
    if shown then expected[#expected + 1] = (shown:gsub("%s+", " ")) end
  end
  local printed = {}
  local env = setmetatable({
    print = function(...)
      local parts = {}
      for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
      printed[#printed + 1] = table.concat(parts, " ")
    end,
  }, {__index = _G})
  files.load(code, "README", env)()
  assert.is_true(#expected >= 4)
  assert.same(expected, printed)
end

describe("the README's examples", function()
  it("one-minute: prints exactly the values written beside each print", function()
    check_example("## One%-minute example")
  end)

  it("coming from bump.lua: prints exactly the values written beside each print", function()
    check_example("## Coming from bump.lua")
  end)

  it("interactions: prints exactly the values written beside each print", function()
    check_example("### Interactions: responses, sensors, actors that meet actors, frame contacts")
  end)
end)
