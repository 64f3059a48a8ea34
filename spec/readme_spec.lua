-- The README's one-minute example must print what the README says it prints.
local files = require("spec.support.files")

describe("the README's one-minute example", function()
  it("prints exactly the values written beside each print", function()
    local readme = files.read("README.md")
    local code = readme:match("## One%-minute example%s+```lua\n(.-)```")
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
  end)
end)
