-- The allocation harness the zero-garbage specs and the benches share
-- (fixtures/garbage.lua): it must count what the code allocates, and only that.
local garbage = require("fixtures.garbage")

-- A call `levels` deep, each level with a few locals: stack, no heap.
local function descend(levels)
  local a, b, c, d = levels, levels, levels, levels
  if levels > 0 then return a + b + c + d + descend(levels - 1) end
  return 0
end

describe("garbage.measure", function()
  it("counts 0 bytes for code that calls deeper in a later step than in its first", function()
    -- The interpreter's stack, shrunk by the harness's full collection, grows back with
    -- the deepest call: before the harness grew the stack first, these steps counted
    -- 9664 bytes on Lua 5.1, 25472 on Lua 5.4 and 4288 on LuaJIT (2026-12-05).
    local sum = 0
    local bytes = garbage.measure(function(i) sum = sum + descend(i * 20) end, 5,
      {jit_off = true})
    assert.are.equal(0, bytes)
    -- steps 1 (twice: the harness's extra one) to 5: 4 * (n (n + 1) / 2) per call
    local expected = 0
    for _, i in ipairs({1, 1, 2, 3, 4, 5}) do expected = expected + 2 * (i * 20) * (i * 20 + 1) end
    assert.are.equal(expected, sum)
  end)

  it("counts what a step allocates", function()
    local kept = {}
    local bytes = garbage.measure(function(i) kept[i] = {i, i, i, i} end, 64, {jit_off = true})
    -- 64 tables of four values: at least 64 * 32 bytes on every interpreter
    assert.is_true(bytes >= 64 * 32, "counted " .. bytes)
    assert.are.equal(64, #kept)
  end)
end)
