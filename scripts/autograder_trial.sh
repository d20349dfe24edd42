#!/usr/bin/env bash
# autograder_trial.sh [--release NAME] [--root DIR] ZIP SUBMISSION_DIR: tries an autograder zip the way Gradescope
# runs it, on a clean root file system made with debootstrap (needs root, debootstrap and unzip, and the network to
# the Debian or Ubuntu archive). It makes DIR (default /tmp/meshedit-trial-NAME) once, a minimal NAME (default
# jammy, Ubuntu 22.04 as on Gradescope's base image; noble is 24.04; bookworm is Debian 12), unzips ZIP into
# DIR/autograder/source, runs its setup.sh there as Gradescope does when the zip is uploaded, copies
# SUBMISSION_DIR's files to DIR/autograder/submission, runs /autograder/run_autograder and prints the results.json
# it wrote (also copied to ./autograder_trial_results.json). A second run with the same DIR skips debootstrap and
# the packages already installed (the zip is unpacked and built afresh): remove DIR for a clean trial.
set -euo pipefail
release=jammy
root=""
while [ $# -gt 0 ]; do
  case "$1" in
    --release) release="$2"; shift 2 ;;
    --root) root="$2"; shift 2 ;;
    -h | --help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
[ $# -eq 2 ] || { echo "usage: autograder_trial.sh [--release NAME] [--root DIR] ZIP SUBMISSION_DIR" >&2; exit 2; }
zip_file="$(realpath "$1")"
submission="$(realpath "$2")"
root="${root:-/tmp/meshedit-trial-$release}"
[ "$(id -u)" -eq 0 ] || { echo "autograder_trial: needs root (debootstrap and chroot)" >&2; exit 1; }
[ -f "$zip_file" ] || { echo "autograder_trial: no zip at $zip_file" >&2; exit 1; }
[ -d "$submission" ] || { echo "autograder_trial: no submission folder at $submission" >&2; exit 1; }
for tool in debootstrap unzip; do
  command -v "$tool" >/dev/null || { echo "autograder_trial: needs $tool (apt-get install $tool)" >&2; exit 1; }
done

case "$release" in
  bookworm | trixie) mirror=http://deb.debian.org/debian; components=main ;;
  jammy | noble) mirror=http://archive.ubuntu.com/ubuntu; components=main,universe ;;
  *) echo "autograder_trial: unknown release $release (jammy, noble, bookworm, trixie)" >&2; exit 2 ;;
esac

mounted=()
keys=""
cleanup() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[$i]}" 2>/dev/null || true; done
  [ -z "$keys" ] || rm -rf "$keys"
}
trap cleanup EXIT

if [ ! -x "$root/bin/bash" ]; then
  keyring=()
  if [ "$mirror" = http://archive.ubuntu.com/ubuntu ] && [ ! -f /usr/share/keyrings/ubuntu-archive-keyring.gpg ]; then
    # Debian does not package Ubuntu's archive key: take it from Ubuntu's own keyring package.
    keys="$(mktemp -d)"
    deb="$(curl -fsSL "$mirror/dists/$release/main/binary-amd64/Packages.gz" | zcat |
      awk '/^Package: /{p=$2} p=="ubuntu-keyring" && /^Filename: / && !f {print $2; f=1}')"
    curl -fsSL -o "$keys/keyring.deb" "$mirror/$deb"
    dpkg-deb -x "$keys/keyring.deb" "$keys/x"
    keyring=(--keyring "$keys/x/usr/share/keyrings/ubuntu-archive-keyring.gpg")
  fi
  script=()
  [ -e "/usr/share/debootstrap/scripts/$release" ] || script=(/usr/share/debootstrap/scripts/gutsy)
  echo "autograder_trial: debootstrap $release into $root"
  debootstrap --variant=minbase --components="$components" "${keyring[@]}" "$release" "$root" "$mirror" "${script[@]}"
  if [ "$components" = main,universe ]; then
    printf 'deb %s %s main universe\ndeb %s %s-updates main universe\n' "$mirror" "$release" "$mirror" "$release" \
      >"$root/etc/apt/sources.list"
  fi
fi

for m in proc sys dev dev/pts; do
  mount --bind "/$m" "$root/$m"
  mounted+=("$root/$m")
done
cp /etc/resolv.conf "$root/etc/resolv.conf"

# Gradescope's layout: the zip unpacked in /autograder/source, run_autograder copied to /autograder/, the student's
# files in /autograder/submission, results expected in /autograder/results/results.json.
rm -rf "$root/autograder/source" "$root/autograder/submission" "$root/autograder/results"
mkdir -p "$root/autograder/source" "$root/autograder/submission" "$root/autograder/results"
unzip -q "$zip_file" -d "$root/autograder/source"
cp "$root/autograder/source/run_autograder" "$root/autograder/run_autograder"
chmod +x "$root/autograder/run_autograder"
cp -r "$submission/." "$root/autograder/submission/"

echo "autograder_trial: setup.sh"
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root bash /autograder/source/setup.sh
echo "autograder_trial: run_autograder"
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root /autograder/run_autograder
results="$root/autograder/results/results.json"
[ -f "$results" ] || { echo "autograder_trial: run_autograder wrote no results.json" >&2; exit 1; }
cp "$results" autograder_trial_results.json
cat "$results"
echo
echo "autograder_trial: $release graded $submission; results in $(pwd)/autograder_trial_results.json"
