// The XML reader for an X3P's main.xml (web/src/io/x3p-xml.js): what well-formed XML 1.0 may
// hold besides elements, and each way a document is not well formed refused naming its line.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseXml } from '../../web/src/io/x3p-xml.js';

const read = (xml, lists) => parseXml(xml, { file: 'main.xml', lists: new Set(lists || []) });

test('elements, namespaces, attributes, comments, processing instructions, CDATA, entities and character references', () => {
  const xml = `\uFEFF<?xml version="1.0" encoding="UTF-8"?>
<!-- before the root -->
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2" a='x > y'>
  <Record1><Revision>ISO5436 - 2000</Revision><?pi inside?>
    <Comment>1 &lt; 2 &amp;&amp; &quot;x&quot; &apos;y&apos; &#181;m &#xB5;m <![CDATA[<raw> & ]]></Comment>
    <Empty/><Empty2 b="1" /></Record1>
  <D>1</D><!-- between --><D>2</D>
  <One>3</One>
</p:ISO5436_2>
<!-- after the root -->
`;
  assert.deepEqual(read(xml, ['One']), {
    ISO5436_2: {
      Record1: { Revision: 'ISO5436 - 2000', Comment: '1 < 2 && "x" \'y\' µm µm <raw> & ', Empty: '', Empty2: '' },
      D: ['1', '2'],
      One: ['3'],
    },
  });
});

test('not well formed: each refused naming the line', () => {
  const cases = [
    ['<a>\n<b>1</b>\n', /^Error: main\.xml, line 3: <a> \(opened on line 1\) is not closed: the document is cut short\?$/],
    ['<a>\n<b>1</c>\n</a>', /^Error: main\.xml, line 2: <\/c> closes <b> \(opened on line 2\)\.$/],
    ['<a>\n<b x="1>', /^Error: main\.xml, line 2: <b>'s attribute x does not end/],
    ['<a><b', /^Error: main\.xml, line 1: the start tag <b> does not end/],
    ['<a b=1></a>', /^Error: main\.xml, line 1: <a>'s attribute b has no quoted value\./],
    ['<a>\n&lol;</a>', /^Error: main\.xml, line 2: the entity "&lol;" is not one XML predefines, and the document declares none\./],
    ['<a>x & y</a>', /^Error: main\.xml, line 1: "&" not followed by an entity reference ending in ";"\./],
    ['<!DOCTYPE a [<!ENTITY x "y">]><a/>', /^Error: main\.xml, line 1: a <!DOCTYPE> declaration/],
    ['<a><!ENTITY x "y"></a>', /^Error: main\.xml, line 1: a "<!" declaration inside <a>\./],
    ['<a/>\n<b/>', /^Error: main\.xml, line 2: "<b\/>" after the root element <\/a>\./],
    ['', /^Error: main\.xml, line 1: no element: the document is empty\./],
    ['garbage', /^Error: main\.xml, line 1: text before the root element: "garbage"\./],
    ['<a><!-- open', /^Error: main\.xml, line 1: a comment that does not end/],
    ['<a><![CDATA[x</a>', /^Error: main\.xml, line 1: a CDATA section that does not end/],
    ['< a/>', /^Error: main\.xml, line 1: a "<" that starts no element name\./],
    [`${'<a>'.repeat(65)}${'</a>'.repeat(65)}`, /^Error: main\.xml, line 1: elements nested more than 64 deep\./],
  ];
  for (const [xml, pattern] of cases) assert.throws(() => read(xml), pattern, JSON.stringify(xml));
});

test('a million nested elements are refused at once, without a stack overflow', () => {
  const started = Date.now();
  assert.throws(() => read('<a>'.repeat(1e6)), /elements nested more than 64 deep/);
  assert.ok(Date.now() - started < 2000);
});
