-- How much of a long randomized spec to run. The primary runs (Lua 5.4, and LuaJIT with
-- the JIT on) run the full counts; Lua 5.1, 5.2, 5.3 and LuaJIT with the JIT off repeat
-- the same seeds (Park-Miller: the same sequence everywhere) over a quarter of them, so
-- every case they check is one the primary runs check too, and results are compared bit
-- for bit by the specs that pin them. That keeps make test inside CI's 10 minutes.
-- BUDGE_FULL=1 runs the full counts everywhere.
--
--   local scale = require("spec.support.scale")
--   for case = 1, scale(40000) do ... end   -- 40000 or 10000
local jit = rawget(_G, "jit")
local full = os.getenv("BUDGE_FULL") == "1" or _VERSION == "Lua 5.4"
  or (jit ~= nil and jit.status() == true)

local scale = {full = full}

---`n` on the primary runs, a quarter of it (rounded up) on the others.
function scale.count(n)
  if full then return n end
  return math.ceil(n / 4)
end

return setmetatable(scale, {__call = function(_, n) return scale.count(n) end})
