"""The Shadowed Volume representation's ShadowTechnique list, as the plugin build wrote it into
the proxy XML (vtkDeepShadow/ParaView/TechniqueListXml), names exactly the technique
registry's names as the deepshadow tool lists them, and the template lists none by hand.
    technique_list.py TEMPLATE.xml.in GENERATED.xml DEEPSHADOW_TOOL
Exit 77 (skipped) when the plugin is not built."""
import os
import re
import subprocess
import sys

template, generated, tool = sys.argv[1:4]
if not os.path.exists(generated):
    print("the ParaView plugin is not built (scripts/build-paraview-plugin.sh): skipped")
    sys.exit(77)


def listed(path):
    text = open(path, encoding="utf-8").read()
    domain = re.search(r'name="ShadowTechnique".*?<StringListDomain[^>]*>(.*?)</StringListDomain>', text, re.S)
    return re.findall(r'<String value="([^"]+)"', domain.group(1)) if domain else None


in_xml = listed(generated) or []
by_hand = listed(template)
said = subprocess.run([tool, "render", "--technique", "no-such-technique"], capture_output=True, text=True).stderr
registry = re.search(r"available: ([^)]*)\)", said)
in_registry = [name.strip() for name in registry.group(1).split(",")] if registry else []
print("proxy XML:", ", ".join(in_xml))
print("registry: ", ", ".join(in_registry))
ok = bool(in_registry) and in_xml == in_registry
print("the same names" if ok else "FAILED: they differ")
if by_hand:
    print("FAILED: the template lists names by hand:", ", ".join(by_hand))
    ok = False
sys.exit(0 if ok else 1)
