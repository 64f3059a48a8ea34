-- The project's own promises: version, rockspec, and loading from a copied folder.
local budge = require("budge")
local lfs = require("lfs")

local files = require("spec.support.files")
local read = files.read

local function load_rockspec()
  local env = {}
  files.load(read("budge-scm-1.rockspec"), "rockspec", env)()
  return env
end

local module_files = files.module_files

describe("the project", function()
  it("has a bare semver _VERSION with a CHANGELOG entry", function()
    assert.matches("^%d+%.%d+%.%d+$", budge._VERSION)
    assert.matches("\n## " .. budge._VERSION:gsub("%.", "%%.") .. " ", read("CHANGELOG.md"))
    assert.equal("MIT", budge._LICENSE)
  end)

  it("lists every module file in the rockspec, under its module name", function()
    local rockspec = load_rockspec()
    assert.equal("3.0", rockspec.rockspec_format)
    assert.equal("builtin", rockspec.build.type)
    assert.equal("busted", rockspec.test.type)
    local listed = {}
    for module_name, path in pairs(rockspec.build.modules) do
      local expected = path:match("^src/(.*)%.lua$"):gsub("/init$", ""):gsub("/", ".")
      assert.equal(expected, module_name)
      listed[#listed + 1] = path
    end
    table.sort(listed)
    assert.same(module_files(), listed)
  end)

  it("loads from a folder copied into a game under another name", function()
    local root = os.tmpname()
    os.remove(root)
    assert(lfs.mkdir(root))
    assert(lfs.mkdir(root .. "/libs"))
    assert(lfs.mkdir(root .. "/libs/budge"))
    local copied = {}
    for _, path in ipairs(module_files()) do
      local target = root .. "/libs/budge/" .. path:match("[^/]+$")
      local file = assert(io.open(target, "wb"))
      file:write(read(path))
      file:close()
      copied[#copied + 1] = target
    end
    local saved_path = package.path
    package.path = root .. "/?.lua;" .. root .. "/?/init.lua"
    local ok, copy = pcall(require, "libs.budge")
    package.path = saved_path
    for name in pairs(package.loaded) do
      if name:match("^libs%.budge") then package.loaded[name] = nil end
    end
    for _, target in ipairs(copied) do os.remove(target) end
    lfs.rmdir(root .. "/libs/budge")
    lfs.rmdir(root .. "/libs")
    lfs.rmdir(root)
    assert.is_true(ok, copy)
    assert.are_not.equal(budge, copy)
    assert.equal(budge._VERSION, copy._VERSION)
    assert.is_true(copy.detect_collision({x = 0, y = 0, width = 2, height = 2},
      {x = 1, y = 1, width = 2, height = 2}))
  end)
end)
