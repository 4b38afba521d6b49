"""The Shadowed Volume representation's ShadowTechnique list (its proxy XML) names exactly
the technique registry's names, as the deepshadow tool lists them.
    technique_list.py REPRESENTATIONS.xml DEEPSHADOW_TOOL"""
import re
import subprocess
import sys

xml, tool = sys.argv[1:3]
text = open(xml, encoding="utf-8").read()
listed = re.search(r'name="ShadowTechnique".*?<StringListDomain[^>]*>(.*?)</StringListDomain>', text, re.S)
in_xml = re.findall(r'<String value="([^"]+)"', listed.group(1)) if listed else []
said = subprocess.run([tool, "render", "--technique", "no-such-technique"], capture_output=True, text=True).stderr
registry = re.search(r"available: ([^)]*)\)", said)
in_registry = [name.strip() for name in registry.group(1).split(",")] if registry else []
print("proxy XML:", ", ".join(in_xml))
print("registry: ", ", ".join(in_registry))
ok = bool(in_registry) and sorted(in_xml) == sorted(in_registry)
print("the same names" if ok else "FAILED: they differ")
sys.exit(0 if ok else 1)
