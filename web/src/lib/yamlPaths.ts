// The plan path (as the validator names it: tree.children[1].params.lift_height) of each line of a block-style
// YAML plan, so an error can be highlighted on its own line. A flow-style value ({...}) stays on its key's line.
interface Entry { indent: number; path: string; item: boolean; count: number }

export function linePaths(text: string): string[] {
  const stack: Entry[] = [{ indent: -1, path: "", item: false, count: 0 }];
  const top = () => stack[stack.length - 1];
  const join = (base: string, key: string) => (base ? `${base}.${key}` : key);
  return text.split("\n").map((raw) => {
    const line = raw.replace(/(^|\s)#.*$/, "");
    if (!line.trim()) return "";
    const indent = line.search(/\S/);
    let rest = line.slice(indent);
    let keyIndent = indent;
    if (rest === "-" || rest.startsWith("- ")) {
      while (stack.length > 1 && (top().indent > indent || (top().indent === indent && top().item))) stack.pop();
      const owner = top();
      const path = `${owner.path}[${owner.count++}]`;
      stack.push({ indent, path, item: true, count: 0 });
      rest = rest.slice(1).trimStart();
      keyIndent = indent + 2;
      if (!rest) return path;
    } else {
      while (stack.length > 1 && top().indent >= indent) stack.pop();
    }
    const m = /^([A-Za-z_][\w-]*)\s*:/.exec(rest);
    if (!m) return top().path;
    const path = join(top().path, m[1]);
    stack.push({ indent: keyIndent, path, item: false, count: 0 });
    return path;
  });
}
