// Validates glTF 2.0 files (.gltf or .glb) with the Khronos glTF validator (npm gltf-validator,
// pinned in package.json; install with `npm install --prefix tests/gltf`, which scripts/test.sh does).
// Usage: node validate.mjs FILE [FILE...]
// For each file prints numErrors / numWarnings / numInfos / numHints and the messages. Exits 0 only
// when every file has 0 errors and 0 warnings, 1 when one has some, 2 when a file cannot be read
// or the validator is not installed.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const require = createRequire(import.meta.url);
const files = process.argv.slice(2);
if (files.length === 0) {
    console.error('usage: node validate.mjs FILE [FILE...]');
    process.exit(2);
}

let validator;
try {
    validator = require('gltf-validator');
} catch (e) {
    console.error('gltf-validator is not installed next to validate.mjs: run scripts/test.sh ' +
                  '(or npm install --prefix tests/gltf) first (' + e.message + ')');
    process.exit(2);
}

const severityNames = ['error', 'warning', 'info', 'hint'];
const maxShown = 50;

async function validate(file) {
    let bytes;
    try {
        bytes = new Uint8Array(fs.readFileSync(file));
    } catch (e) {
        console.error(`${file}: cannot read: ${e.message}`);
        return 2;
    }
    let report;
    try {
        report = await validator.validateBytes(bytes, {
            uri: path.basename(file),
            maxIssues: 0,  // unlimited
            writeTimestamp: false,
            // Buffers that are neither data URIs nor the GLB BIN chunk are read next to the file.
            externalResourceFunction: (uri) =>
                new Promise((resolve, reject) => {
                    const full = path.resolve(path.dirname(file), decodeURIComponent(uri));
                    fs.readFile(full, (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
                }),
        });
    } catch (e) {
        console.log(`${file}: the validator could not read it: ${e}`);
        return 1;
    }
    const issues = report.issues;
    console.log(`${file}: validator ${report.validatorVersion}`);
    console.log(`numErrors: ${issues.numErrors}`);
    console.log(`numWarnings: ${issues.numWarnings}`);
    console.log(`numInfos: ${issues.numInfos}`);
    console.log(`numHints: ${issues.numHints}`);
    for (const m of issues.messages.slice(0, maxShown))
        console.log(`  ${severityNames[m.severity] ?? m.severity} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
    if (issues.messages.length > maxShown) console.log(`  ... ${issues.messages.length - maxShown} more`);
    return issues.numErrors === 0 && issues.numWarnings === 0 ? 0 : 1;
}

let status = 0;
for (const file of files) status = Math.max(status, await validate(file));
process.exit(status);
