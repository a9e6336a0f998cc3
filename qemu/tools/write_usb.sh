#!/usr/bin/env bash
# make usb DEVICE=/dev/sdX: writes the ISO to a USB stick, after refusing anything that does not
# look like one. Refuses: a device that is not a whole disk, one that is neither removable nor on
# USB, one with a mounted (or swapped-on) partition, one above 64 GiB (unless FORCE=1). Shows what
# it will overwrite and asks for the device's name to be typed again (YES=1: does not ask).
# MODEXLAB_SYSFS, MODEXLAB_PROC and MODEXLAB_DEV (default /sys, /proc and /dev) let the tests fake
# a machine's disks.
set -euo pipefail

iso=${1:-}
device=${DEVICE:-}
sysfs=${MODEXLAB_SYSFS:-/sys}
proc=${MODEXLAB_PROC:-/proc}
dev=${MODEXLAB_DEV:-/dev}
limit_gib=64

refuse() {
    echo "make usb: $*" >&2
    echo "make usb: nothing was written" >&2
    exit 1
}

[ -n "$iso" ] && [ -f "$iso" ] || refuse "no ISO at '$iso' (make iso builds it)"
[ -n "$device" ] || refuse "name the stick: make usb DEVICE=/dev/sdX (lsblk lists the disks)"
case "$device" in
/dev/*) ;;
*) refuse "DEVICE=$device: a device path, /dev/NAME" ;;
esac
name=${device#/dev/}
case "$name" in
*/* | "") refuse "DEVICE=$device: a disk directly under /dev" ;;
esac
block="$sysfs/block/$name"
if [ ! -d "$block" ]; then
    [ -e "$sysfs/class/block/$name/partition" ] && refuse "$device is a partition: name the whole stick (the disk it belongs to)"
    refuse "$device is not a disk this machine has ($block missing)"
fi
target="$dev/$name"  # (the device itself, but in the tests)
[ -e "$target" ] || refuse "$device does not exist"

removable=$(cat "$block/removable" 2>/dev/null || echo 0)
on_usb=0
real=$(readlink -f "$block")
case "${real#"$(readlink -f "$sysfs")"}" in  # (a USB disk's sysfs path runs through its bus: .../usb2/2-1/...)
*/usb[0-9]*/*) on_usb=1 ;;
esac
[ "$removable" = 1 ] || [ "$on_usb" = 1 ] ||
    refuse "$device is neither removable nor on USB (a fixed disk?): refused"

sectors=$(cat "$block/size")
bytes=$((sectors * 512))
gib=$(((bytes + (1 << 30) - 1) >> 30))
if [ "$bytes" -gt $((limit_gib << 30)) ] && [ "${FORCE:-0}" != 1 ]; then
    refuse "$device holds ${gib} GiB, more than ${limit_gib} GiB: not the usual stick (FORCE=1 to write it anyway)"
fi

# the disk and its partitions: none may be mounted or in use as swap
parts=("$name")
for p in "$block"/"$name"*; do
    [ -e "$p/partition" ] && parts+=("$(basename "$p")")
done
for p in "${parts[@]}"; do
    if grep -qE "^/dev/$p " "$proc/mounts" 2>/dev/null; then
        refuse "/dev/$p is mounted at $(awk -v d="/dev/$p" '$1 == d {print $2; exit}' "$proc/mounts"): unmount it first"
    fi
    if grep -qE "^/dev/$p[[:space:]]" "$proc/swaps" 2>/dev/null; then refuse "/dev/$p is in use as swap"; fi
done

model=$(cat "$block/device/model" 2>/dev/null | sed 's/ *$//' || true)
vendor=$(cat "$block/device/vendor" 2>/dev/null | sed 's/ *$//' || true)
echo "make usb: about to overwrite $device, whole:"
echo "  ${vendor:-?} ${model:-?}, ${gib} GiB ($bytes bytes), removable=$removable, usb=$on_usb"
for p in "${parts[@]:1}"; do
    size=$(($(cat "$block/$p/size") * 512))
    echo "  partition /dev/$p: $size bytes"
done
if command -v lsblk >/dev/null && [ "$sysfs" = /sys ]; then lsblk -o NAME,SIZE,TYPE,FSTYPE,LABEL,MODEL "$device" | sed 's/^/  /' || true; fi
echo "  with $iso ($(stat -c %s "$iso") bytes); everything on it now is lost"

if [ "${YES:-0}" != 1 ]; then
    printf 'make usb: type %s to go on: ' "$name"
    read -r answer || answer=""
    [ "$answer" = "$name" ] || refuse "not confirmed"
fi
dd if="$iso" of="$target" bs=4M conv=fsync status=progress
sync
echo "make usb: $device written; it boots the ISO (docs/real-pc.md)"
