#!/usr/bin/env node
// Validates a .glb with the Khronos glTF validator.
// Usage: node validate.mjs <file.glb>   -> exit 1 when the validator reports errors.
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import * as validator from 'gltf-validator';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate.mjs <file.glb>');
  process.exit(2);
}

const SEVERITY = ['error', 'warning', 'info', 'hint'];
const SHOW = 10; // messages printed

try {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(file)), {
    uri: basename(file),
    maxIssues: 0, // count everything
    // a .glb is self-contained: refuse external buffers/images instead of reading the disk
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource not allowed: ${uri}`)),
  });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  console.log(`gltf-validator ${report.validatorVersion}: ${file}`);
  console.log(`  ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
  for (const m of messages.slice(0, SHOW)) {
    console.log(`  [${SEVERITY[m.severity] ?? m.severity}] ${m.code} at ${m.pointer ?? `byte ${m.offset}`}: ${m.message}`);
  }
  if (messages.length > SHOW) console.log(`  ... ${messages.length - SHOW} more`);
  const info = report.info ?? {};
  console.log(`  draw calls=${info.drawCallCount ?? '?'} triangles=${info.totalTriangleCount ?? '?'} animations=${info.animationCount ?? '?'}`);
  process.exit(numErrors > 0 ? 1 : 0);
} catch (err) {
  // validateBytes rejects when the input is not glTF/GLB at all
  console.error(`validate.mjs: cannot validate ${file}: ${err?.message ?? err}`);
  process.exit(1);
}
