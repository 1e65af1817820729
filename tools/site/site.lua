-- pandoc Lua filter of scripts/site.sh: one Markdown page of the repository to one page of the site.
--   * display math with \tag{N}: the tag is taken out of the TeX (MathML has no \tag) and shown as
--     "(N)" at the right, the equation gets the id eq-N;
--   * a relative link to a Markdown file X.md (with or without #anchor) points to X.html;
--   * every relative link and image is appended to the file $SITE_LINKS as "PAGE<TAB>TARGET", so
--     that the script can make the pages they point to and check that the files exist.
-- $SITE_PAGE is the page's path in the repository (e.g. lessons/03-path-tracing/README.md).

local page = os.getenv("SITE_PAGE") or ""
local links = os.getenv("SITE_LINKS")

local function record(target)
  if links == nil then return end
  local f = io.open(links, "a")
  if f then
    f:write(page, "\t", target, "\n")
    f:close()
  end
end

local function relative(target)
  return not target:match("^%a[%w+.-]*:") and not target:match("^#") and not target:match("^/")
end

function Math(m)
  if m.mathtype ~= "DisplayMath" then return nil end
  local tag = m.text:match("\\tag%*?{([^}]*)}")
  if tag == nil then return nil end
  local text = m.text:gsub("\\tag%*?{[^}]*}", "")
  return pandoc.Span({ pandoc.Math("DisplayMath", text), pandoc.Span({ pandoc.Str("(" .. tag .. ")") },
    pandoc.Attr("", { "eqno" })) }, pandoc.Attr("eq-" .. tag, { "equation" }))
end

function Link(l)
  if relative(l.target) then
    record(l.target)
    local path, anchor = l.target:match("^([^#]*)(#?.*)$")
    if path:match("%.md$") then l.target = path:gsub("%.md$", ".html") .. anchor end
  end
  return l
end

function Image(i)
  if relative(i.src) then record(i.src) end
  return i
end
