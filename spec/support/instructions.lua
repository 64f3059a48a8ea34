-- Interpreter instructions a call runs, in hundreds, counted by a debug hook: what the
-- specs that check a cost's growth (k log k, not k^2) compare, with no timing. On LuaJIT
-- the hook counts in the interpreter alone, so the JIT is off (and its traces flushed)
-- while it counts, and on again after.
--
--   local instructions = require("spec.support.instructions")
--   local hundreds = instructions(function() world:move(actor, 3, 0) end)
local jit = rawget(_G, "jit")

---@param fn fun() the call to count (warm it up first: the first calls grow tables)
---@return integer hundreds of virtual machine instructions
return function(fn)
  if jit then
    jit.off()
    jit.flush()
  end
  local count = 0
  debug.sethook(function() count = count + 1 end, "", 100)
  fn()
  debug.sethook()
  if jit then jit.on() end
  return count
end
