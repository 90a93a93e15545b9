// The maps hold: every file or folder that README.md, core/README.md and docs/*.md name exists,
// and every relative link in them reaches a file (and, for a heading, that heading).
// Checked: links [text](path#anchor) and ![alt](path), relative to the page; and paths in
// backticks, `core/gear/` or `wasm/lib/x3p.js`, relative to the repository when their first
// folder is one of the repository's, or, as the pages name them for short, under the page's own
// folder (`inspection/indicator.py` in docs/), web/src/ (`views/report.js`) or core/
// (`grinding/envelope.h`).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync, readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

// The pages with maps and links.
export function mapPages(root = ROOT) {
  const docs = readdirSync(path.join(root, 'docs')).filter((f) => f.endsWith('.md')).map((f) => `docs/${f}`);
  return ['README.md', 'core/README.md', ...docs];
}

// The folders of the repository a backticked path may start with (what the build writes, build/
// and test-output/, is not in it), and the folders a page names paths under for short.
const TOP = ['core', 'data', 'docs', 'tests', 'wasm', 'web', '.ci'];
const TOP_FILES = ['README.md', 'hobsharp.sh', 'CMakeLists.txt', 'package.json', 'package-lock.json'];
const SHORT_BASES = ['web/src', 'core'];

// GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens.
export function slug(heading) {
  return heading.trim().toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').replace(/\s/g, '-');
}

function anchorsOf(text) {
  const seen = new Map();
  const out = new Set();
  for (const m of stripCode(text).matchAll(/^#{1,6}\s+(.*?)\s*#*\s*$/gm)) {
    const s = slug(m[1]);
    const n = seen.get(s) ?? 0;
    out.add(n ? `${s}-${n}` : s);
    seen.set(s, n + 1);
  }
  return out;
}

// The text without its indented and fenced code blocks (a `#` comment there is no heading).
function stripCode(text) {
  return text.replace(/^```[\s\S]*?^```/gm, '').replace(/^(?: {4}|\t).*$/gm, '');
}

// The relative links of a page: [text](target) and ![alt](target), not http(s) or mailto.
export function linksOf(text) {
  const out = [];
  for (const m of stripCode(text).matchAll(/!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)/g)) {
    const target = m[1];
    if (/^[a-z]+:/i.test(target)) continue;
    out.push(target);
  }
  return out;
}

// The paths a page names in backticks: repository paths, and the short ones under SHORT_BASES.
export function namedPaths(text, page = 'README.md') {
  const own = path.dirname(page) === '.' ? [] : [path.dirname(page)];
  const out = [];
  for (const m of text.matchAll(/`([^`\s]+)`/g)) {
    const p = m[1].replace(/[.,;:]$/, '');
    if (!/^[\w.\-/]+$/.test(p) || p.includes('..') || /^\d/.test(p)) continue;
    const first = p.split('/')[0];
    if (TOP_FILES.includes(p) || (p.includes('/') && TOP.includes(first))) out.push({ path: p, bases: [''] });
    else if (p.includes('/') && /\.(h|cpp|js|mjs|json|md|cmake|py|svg|png|csv)$|\/$/.test(p)) {
      const bases = [...own, ...SHORT_BASES].filter((b) => existsSync(path.join(ROOT, b, first)));
      if (bases.length) out.push({ path: p, bases });
    }
  }
  return out;
}

// What is wrong in one page's maps and links, as sentences (none when all is well).
export function brokenIn(page, text, root = ROOT) {
  const problems = [];
  for (const { path: p, bases } of namedPaths(text, page)) {
    if (!bases.some((b) => existsSync(path.join(root, b, p)))) {
      problems.push(`${page}: \`${p}\` names no file or folder${bases[0] ? ` under ${bases.join(' or ')}/` : ''}`);
    }
  }
  for (const target of linksOf(text)) {
    const [file, anchor] = target.split('#');
    const resolved = file && path.resolve(root, path.dirname(page), decodeURIComponent(file));
    if (file && !existsSync(resolved)) { problems.push(`${page}: the link (${target}) reaches no file`); continue; }
    const linked = !file ? text : resolved.endsWith('.md') && statSync(resolved).isFile() ? readFileSync(resolved, 'utf8') : null;
    if (anchor && linked !== null && !anchorsOf(linked).has(decodeURIComponent(anchor))) {
      problems.push(`${page}: the link (${target}) reaches no heading #${anchor}`);
    }
  }
  return problems;
}

test('every path named and every relative link in README.md, core/README.md and docs/ exists', () => {
  const problems = mapPages().flatMap((page) => brokenIn(page, readFileSync(path.join(ROOT, page), 'utf8')));
  assert.deepEqual(problems, []);
});

test('the check finds a path or a link that is not there', () => {
  const page = 'docs/example.md';
  const text = [
    '| `core/gear/` | `core/nowhere/` | `wasm/cli-x3p.mjs` | `views/report.js` | `views/nothing.js` |',
    '[case](case-format.md#the-inspection) [gone](no-such-page.md) [bad heading](conventions.md#no-such-heading)',
    '![shot](screenshot.png) [self](#a-heading)',
    '## A heading',
    '    `core/in-an-example/` [not a link](nowhere.md) is code, yet the path is still checked',
  ].join('\n');
  assert.deepEqual(brokenIn(page, text), [
    'docs/example.md: `core/nowhere/` names no file or folder',
    'docs/example.md: `views/nothing.js` names no file or folder under web/src/',
    'docs/example.md: `core/in-an-example/` names no file or folder',
    'docs/example.md: the link (no-such-page.md) reaches no file',
    'docs/example.md: the link (conventions.md#no-such-heading) reaches no heading #no-such-heading',
  ]);
});

test('the anchors are GitHub\'s', () => {
  assert.equal(slug("The wheel's profile"), 'the-wheels-profile');
  assert.equal(slug('1. Radial alignment: `inspection.radialAlignment`, µm'), '1-radial-alignment-inspectionradialalignment-µm');
});
